#include "view/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "driver/options.h"
#include "driver/prepare_script.h"
#include "gl/window_frame.h"
#include "image/text.h"
#include "plan/dependencies.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

// Commands arrive from --exec, from standard input (a thread of its own, so
// a silent stdin never blocks the window) and from the panel's buttons.
class CommandQueue {
public:
    void push(std::string line) {
        std::lock_guard<std::mutex> lock(mutex_);
        lines_.push_back(std::move(line));
    }
    std::vector<std::string> take() {
        std::lock_guard<std::mutex> lock(mutex_);
        std::vector<std::string> out(lines_.begin(), lines_.end());
        lines_.clear();
        return out;
    }

private:
    std::mutex mutex_;
    std::deque<std::string> lines_;
};

class Viewer {
public:
    Viewer(const ViewOptions& o, GlfwWindow& window, int width, int height)
        : options_(o), window_(window), width_(width), height_(height) {}

    // The script at w x h, parsed, planned and prepared on a renderer of its
    // own. False (with diagnostics) when anything failed; `renderer` is then null.
    bool prepareAt(int w, int h, LoadedScript& next, std::unique_ptr<Renderer>& renderer, Diagnostics& diags) {
        ScriptRequest request;
        request.script = options_.script;
        request.plan.includeDirs = options_.includeDirs;
        request.plan.width = w;
        request.plan.height = h;
        // Every target can be looked at in the pass inspector, so every pass
        // that draws into one runs, read by a later pass or not.
        for (int unit = 0; unit < 32; ++unit) request.plan.keepTargets.insert(unit);
        renderer = prepareScript(request, [&](const char* n) { return window_.getProcAddress(n); }, diags, next);
        return renderer != nullptr;
    }

    // Loads the script at the current size. On any error the last good
    // script, renderer and values stay; the error is shown and printed.
    void load(const char* why) {
        Diagnostics diags;
        LoadedScript next;
        std::unique_ptr<Renderer> renderer;
        prepareAt(width_, height_, next, renderer, diags);
        watchFilesOf(next.plan);
        std::ostringstream printed;
        printDiagnostics(diags, next.sources, printed);
        std::cerr << printed.str();
        if (!renderer) {
            s_.error = printed.str().empty() ? "the script could not be loaded" : printed.str();
            s_.status = fmt::format("{} failed; keeping the last good picture", why);
            std::cerr << "glimmer view: " << s_.status << "\n";
            return;
        }
        UniformValues values(next.plan);
        if (s_.good && s_.values) values.carryOver(s_.good->plan, *s_.values, next.plan);
        else
            for (const auto& a : options_.sets) values.applySet(next.plan, a, diags);
        s_.good = std::move(next);
        s_.renderer = std::move(renderer);
        s_.values = values;
        s_.drawnWith.reset();
        s_.error.clear();
        s_.drawAll = true;
        if (s_.shownTexture >= int(s_.good->plan.textures.size())) s_.shownTexture = -1;
        s_.status = why;
        std::cerr << "glimmer view: " << why << "\n";
    }

    int run(CommandQueue& queue) {
        std::string why;
        frame_ = WindowFrame::create([&](const char* n) { return window_.getProcAddress(n); }, why);
        if (!frame_) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitScriptError;
        }
        load("loaded");
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
        ImGui_ImplGlfw_InitForOpenGL(window_.handle(), true);
        ImGui_ImplOpenGL3_Init("#version 130");
        auto lastPoll = Clock::now(), lastTick = Clock::now();
        bool quit = false;
        int resizeW = width_, resizeH = height_;
        auto resizeAt = Clock::time_point::max();
        while (!quit && !glfwWindowShouldClose(window_.handle())) {
            glfwWaitEventsTimeout(0.02);
            auto now = Clock::now();
            if (s_.playing) s_.time += std::chrono::duration<double>(now - lastTick).count();
            lastTick = now;

            // A resize re-plans at the new size once the user stops dragging.
            int fbw = 0, fbh = 0;
            glfwGetFramebufferSize(window_.handle(), &fbw, &fbh);
            if (fbw > 0 && fbh > 0 && (fbw != resizeW || fbh != resizeH)) {
                resizeW = fbw;
                resizeH = fbh;
                resizeAt = now + std::chrono::milliseconds(150);
            }
            if (now >= resizeAt) {
                resizeAt = Clock::time_point::max();
                if (resizeW != width_ || resizeH != height_) {
                    width_ = resizeW;
                    height_ = resizeH;
                    load(fmt::format("resized to {}x{}", width_, height_).c_str());
                }
            }
            if (now - lastPoll >= std::chrono::milliseconds(25)) {
                lastPoll = now;
                auto changed = watch_.poll(now);
                if (!changed.empty()) load(fmt::format("reloaded after a change to {}", changed.front()).c_str());
            }
            for (const auto& line : queue.take()) quit |= execute(line);
            if (quit) break;

            if (!ImGui::GetIO().WantCaptureKeyboard && glfwGetKey(window_.handle(), GLFW_KEY_S) == GLFW_PRESS && !sDown_)
                save("glimmer.png", false);
            sDown_ = glfwGetKey(window_.handle(), GLFW_KEY_S) == GLFW_PRESS;

            mouse();
            renderScene();
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            for (const auto& c : drawPanel(s_)) quit |= apply(c);
            if (s_.showValues) {
                std::string text = overlayText(s_);
                ImGui::GetForegroundDrawList()->AddText(ImVec2(float(fbw) - 260.f, 12.f), IM_COL32(255, 255, 255, 255),
                                                        text.c_str());
            }
            ImGui::Render();
            glfwGetFramebufferSize(window_.handle(), &fbw, &fbh);
            if (frame_) frame_->begin(fbw, fbh, 0.12f, 0.12f, 0.14f);
            if (s_.renderer) s_.renderer->present(s_.shownTexture, fbw, fbh);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            glfwSwapBuffers(window_.handle());
        }
        s_.renderer.reset();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        return kExitOk;
    }

private:
    void watchFilesOf(const Plan& plan) {
        std::set<std::string> files = {options_.script};
        for (const auto& p : watch_.paths()) files.insert(p);  // keep what a broken edit may still need
        for (const auto& prog : plan.programs)
            for (const auto& st : prog.stages) files.insert(st.path);
        for (const auto& t : plan.textures) {
            if (t.source == TextureDecl::Source::File) files.insert(t.path);
            files.insert(t.facePaths.begin(), t.facePaths.end());  // all six faces of a cube map
        }
        for (const auto& m : plan.meshes)
            if (!m.path.empty()) files.insert(m.path);  // OBJ models
        std::vector<std::string> list(files.begin(), files.end());
        if (list != watch_.paths()) watch_.watch(list);
    }

    void mouse() {
        ImGuiIO& io = ImGui::GetIO();
        GLFWwindow* w = window_.handle();
        double x = 0, y = 0;
        glfwGetCursorPos(w, &x, &y);
        bool down = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (down && dragging_ && !io.WantCaptureMouse) {
            s_.yaw += float(x - lastX_) * 0.4f;
            s_.pitch += float(y - lastY_) * 0.4f;
            s_.sceneMoved = true;
        }
        dragging_ = down && !io.WantCaptureMouse;
        lastX_ = x;
        lastY_ = y;
        if (!io.WantCaptureMouse && io.MouseWheel != 0) {
            s_.zoom = std::clamp(s_.zoom * std::pow(1.1f, io.MouseWheel), 0.05f, 20.f);
            s_.sceneMoved = true;
        }
        if (s_.renderer) {
            glm::mat4 m = glm::scale(glm::mat4(1.f), glm::vec3(s_.zoom));
            m = glm::rotate(m, glm::radians(s_.pitch), glm::vec3(1, 0, 0));
            m = glm::rotate(m, glm::radians(s_.yaw), glm::vec3(0, 1, 0));
            s_.renderer->setSceneTransform(m);
        }
    }

    // Runs the passes that changed since the picture was drawn: all after a
    // load, the ones reading a changed Program's uniforms, the ones reading
    // Timer while time runs; nothing when nothing changed.
    void renderScene() {
        if (!s_.renderer || !s_.good) return;
        const Plan& plan = s_.good->plan;
        Change change;
        change.everything = s_.drawAll;
        change.screen = s_.sceneMoved;
        s_.sceneMoved = false;
        if (s_.drawnWith) change.programs = s_.values->programsDifferingFrom(*s_.drawnWith);
        if (s_.time != s_.drawnTime)
            for (size_t p = 0; p < plan.programs.size(); ++p)
                if (s_.renderer->usesTimer(int(p))) change.programs.insert(int(p));
        std::vector<bool> only = passesToRun(plan, change);
        bool any = false;
        for (bool b : only) any |= b;
        if (!any) return;
        auto start = Clock::now();
        s_.lastTimings.clear();
        s_.renderer->render(*s_.values, s_.time, &s_.lastTimings, &only);
        s_.lastFrameMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        s_.drawnWith = s_.values;
        s_.drawnTime = s_.time;
        s_.drawAll = false;
        // The numeric health badge reads every target back: at most twice a
        // second, so dragging a slider stays smooth.
        auto now = Clock::now();
        if (now - lastHealth_ >= std::chrono::milliseconds(500)) {
            s_.health = measureHealth(*s_.renderer, plan);
            lastHealth_ = now;
            std::string report;
            for (const auto& h : s_.health)
                if (h.bad()) report += formatHealth(h) + "\n";
            if (report != lastReport_) std::cerr << report;  // once per change, for scripts watching stderr
            lastReport_ = report;
        }
    }

    bool execute(const std::string& line) {
        std::string error;
        auto c = parseViewCommand(line, error);
        if (!c) {
            if (!error.empty()) std::cerr << "glimmer view: " << error << "\n";
            return false;
        }
        return apply(*c);
    }

    bool apply(const ViewCommand& c) {
        switch (c.kind) {
        case ViewCommand::Kind::Quit: return true;
        case ViewCommand::Kind::Reload: load("reloaded"); break;
        case ViewCommand::Kind::Set: {
            if (!s_.good) break;
            Diagnostics d;
            s_.values->applySet(s_.good->plan, c.name + "=" + c.text, d);
            std::ostringstream out;
            printDiagnostics(d, s_.good->sources, out);
            for (const auto& diag : d.all()) std::cerr << "glimmer view: " << severityName(diag.severity) << ": " << diag.message << "\n";
            break;
        }
        case ViewCommand::Kind::Save: save(c.name, c.unit == -2); break;
        case ViewCommand::Kind::Show:
            if (c.unit < 0) s_.shownTexture = -1;
            else if (s_.good && s_.good->plan.finalUnits.count(c.unit)) s_.shownTexture = s_.good->plan.finalUnits.at(c.unit);
            else std::cerr << "glimmer view: show: no texture on unit " << c.unit << "\n";
            break;
        }
        return false;
    }

    // The same pixels `glimmer render` writes for these values and this size;
    // with the overlay on, the values are burned in, so a handout records its
    // own parameters.
    void save(const std::string& file, bool hardcopy) {
        if (!s_.renderer || !s_.good) {
            std::cerr << "glimmer view: nothing to save yet\n";
            return;
        }
        Image img;
        if (hardcopy) {
            img = renderAtSize(s_.hardcopy[0], s_.hardcopy[1]);
        } else {
            renderScene();  // a command may have changed values since the last frame
            img = s_.renderer->readScreen();
        }
        if (img.empty()) return;
        if (s_.showValues) drawText(img, 8, 8, overlayText(s_));
        std::string why;
        if (writePng(file, img, why)) s_.status = "saved " + file;
        else s_.status = why;
        std::cerr << "glimmer view: " << s_.status << "\n";
    }

    // glman's hardcopy: the same script and values drawn at any size on a
    // renderer of its own, which goes away afterwards.
    Image renderAtSize(int w, int h) {
        if (w < 1 || h < 1 || w > 16384 || h > 16384) return {};
        Diagnostics diags;
        LoadedScript ls;
        std::unique_ptr<Renderer> r;
        if (!prepareAt(w, h, ls, r, diags)) return {};
        UniformValues v(ls.plan);
        v.carryOver(s_.good->plan, *s_.values, ls.plan);
        r->render(v, s_.time);
        return r->readScreen();
    }

    const ViewOptions& options_;
    GlfwWindow& window_;
    int width_, height_;
    ViewerState s_;
    FileWatch watch_;
    bool sDown_ = false;
    Clock::time_point lastHealth_{};
    std::string lastReport_;
    bool dragging_ = false;
    double lastX_ = 0, lastY_ = 0;
    std::unique_ptr<WindowFrame> frame_;  // clears the window; the viewer itself calls no GL
};

// The window's starting size: --size, else the script's WindowSize, else 600x600.
void initialSize(const ViewOptions& o, int& w, int& h) {
    w = h = 600;
    if (!o.size.empty() && parseSize(o.size, w, h)) return;
    Diagnostics d;
    LoadedScript ls;
    if (loadScript(o.script, {}, d, ls)) {
        w = ls.plan.width;
        h = ls.plan.height;
    }
}

}  // namespace

int runView(const ViewOptions& o) {
    int w = 600, h = 600;
    if (!o.size.empty() && !parseSize(o.size, w, h)) {
        std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT (1 to 16384 each)\n", o.size);
        return kExitUsage;
    }
    for (const auto& line : splitCommands(o.exec)) {
        std::string error;
        if (!parseViewCommand(line, error) && !error.empty()) {
            std::cerr << "glimmer: error: --exec: " << error << "\n";
            return kExitUsage;
        }
    }
    initialSize(o, w, h);
    std::string why;
    auto window = GlfwWindow::open(w, h, "Glimmer - " + o.script, why);
    if (!window) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    CommandQueue queue;
    for (const auto& line : splitCommands(o.exec)) queue.push(line);
    if (o.readStdin) {
        std::thread([&queue] {
            for (std::string line; std::getline(std::cin, line);) queue.push(line);
        }).detach();
    }
    Viewer viewer(o, *window, w, h);
    return viewer.run(queue);
}

}  // namespace glimmer
