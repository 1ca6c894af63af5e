#include "view/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "backends/glfw_window.h"
#include "pipeline/options.h"
#include "process/output_guard.h"
#include "pipeline/prepare_script.h"
#include "gl/window_frame.h"
#include "plan/dependencies.h"
#include "view/file_monitor.h"
#include "view/panel.h"
#include "view/view_model.h"
#include "view/view_keys.h"
#include "view/viewer_core.h"
#include "view/wakeups.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

// While a frame draws and nothing asks for the window, slices follow each
// other without a window frame in between, except to show progress this often.
constexpr auto kProgressEvery = std::chrono::milliseconds(100);

class Viewer {
public:
    Viewer(const ViewOptions& o, GlfwWindow& window, int width, int height)
        : options_(o), window_(window), width_(width), height_(height), reqW_(width), reqH_(height),
          core_({o.script, o.includeDirs, o.sets, o.standIns, o.sandbox},
                [&window](const char* n) { return window.getProcAddress(n); }),
          s_(core_.state()) {
        s_.keyHint = "H hides this panel, F fullscreen, Q quits";
    }

    // Prints errors first, then only the warnings not printed before (a
    // reload does not repeat the seed's warnings every time), and keeps both
    // for the panel.
    void report() {
        std::string errors, warnings;
        int repeated = 0;
        for (const auto& e : s_.errors) errors += e.text + "\n";
        for (const auto& w : s_.warnings) {
            if (printedWarnings_.insert(w.text).second) warnings += w.text + "\n";
            else ++repeated;
        }
        std::cerr << errors << warnings;
        if (!s_.errors.empty() || !warnings.empty())
            std::cerr << fmt::format("{} error{}, {} warning{}{}\n", s_.errors.size(), s_.errors.size() == 1 ? "" : "s",
                                     s_.warnings.size(), s_.warnings.size() == 1 ? "" : "s",
                                     repeated ? fmt::format(" ({} shown before)", repeated) : "");
    }

    // Loads the script at the current size. On any error the last good
    // script, renderer and values stay; the error is shown and printed.
    void load(const char* why) {
        Diagnostics diags;
        SourceTexts sources;
        Plan plan;
        bool loaded = core_.load(width_, height_, diags, sources, &plan);
        watchFilesOf(plan);
        report();
        if (!loaded) {
            s_.status = fmt::format("{} failed; keeping the last good picture", why);
            std::cerr << "glimmer view: " << s_.status << "\n";
            return;
        }
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
        GLFWwindow* w = window_.handle();
        installWakeCallbacks(w);
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
        ImGui_ImplGlfw_InitForOpenGL(w, true);
        ImGui_ImplOpenGL3_Init("#version 130");
        float sx = 1, sy = 1;
        if (options_.uiScale <= 0) glfwGetWindowContentScale(w, &sx, &sy);
        applyUiScale(chooseUiScale(options_.uiScale, sx, sy), false);
        gWindowAlive = true;
        FileWaker waker(monitor_.notifyFd());

        auto lastTick = Clock::now();
        bool quit = false;
        int framesLeft = 3;  // ImGui settles its layout over a frame or two
        while (!quit && !glfwWindowShouldClose(w)) {
            // Sleep until something happens: input, a command, a file the
            // kernel reports, a resize to settle; a running Timer draws at 50 Hz.
            ImGuiIO& io = ImGui::GetIO();
            bool animating = s_.playing && timerUsed();
            const bool busy = core_.drawing();
            if (framesLeft > 0 || busy) glfwPollEvents();
            else if (animating) glfwWaitEventsTimeout(0.02);
            else if (monitor_.busy() || resizeAt_ != Clock::time_point::max()) glfwWaitEventsTimeout(0.025);
            else if (io.WantTextInput) glfwWaitEventsTimeout(0.5);  // the text cursor blinks
            else glfwWaitEvents();
            bool draw = framesLeft > 0 || animating;
            if (framesLeft > 0) --framesLeft;
            auto now = Clock::now();
            if (gInput.exchange(false)) {
                framesLeft = 3;
                draw = true;
                lastInput_ = now;
            }
            if (s_.playing) s_.time += std::chrono::duration<double>(now - lastTick).count();
            lastTick = now;

            followContentScale();
            draw |= followWindowSize(now);
            auto changed = monitor_.poll(now);
            if (!changed.empty()) {
                load(fmt::format("reloaded after a change to {}", changed.front()).c_str());
                draw = true;
            }
            for (const auto& line : queue.take()) {
                bool onlyAsked = false;
                quit |= execute(line, onlyAsked);
                draw = true;
                // A command that only asks does not make the user busy (the
                // benchmark's `frames` must not shorten the slices it measures).
                if (!onlyAsked) lastInput_ = now;
            }
            if (quit) break;
            if (!draw && busy) {
                // Nothing asked for the window: draw more of the frame, and
                // show how far it got now and then.
                if (Clock::now() - core_.lastFrameShown() < kProgressEvery) {
                    renderScene();
                    if (core_.drawing()) continue;
                }
                draw = true;  // progress to show, or the finished picture
            }
            if (!draw) continue;

            int fbw = 0, fbh = 0;
            glfwGetFramebufferSize(w, &fbw, &fbh);
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            quit |= keys();
            mouse(fbw, fbh);
            renderScene();
            std::vector<ViewCommand> asked;
            if (s_.panelShown) asked = panel(fbw, fbh);
            core_.drawValues();
            ImGui::Render();
            frame_->begin(fbw, fbh, 0.12f, 0.12f, 0.14f);
            presentPicture(fbw, fbh);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            glfwSwapBuffers(w);
            core_.noteFrame();
            for (const auto& c : asked) quit |= apply(c);
            layout();
        }
        gWindowAlive = false;
        core_.releaseGl();  // while the context is still current
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        return kExitOk;
    }

private:
    bool timerUsed() const {
        if (!s_.renderer || !s_.good) return false;
        for (size_t p = 0; p < s_.good->plan.programs.size(); ++p)
            if (s_.renderer->usesTimer(int(p))) return true;
        return false;
    }

    // Where the picture is drawn in the window (top-left origin): its exact
    // size at the top left, or fitted into what the panel leaves in fullscreen.
    void pictureRect(int fbw, int fbh, int& x, int& y, int& w, int& h) const {
        x = y = 0;
        if (fullscreen_) {
            w = std::max(1, fbw - (s_.panelShown ? panelW_ : 0));
            h = fbh;
            return;
        }
        w = width_;
        h = height_;
    }

    void presentPicture(int fbw, int fbh) {
        int x, y, w, h;
        pictureRect(fbw, fbh, x, y, w, h);
        glimmer::presentPicture(s_, fbh, x, y, w, h);
    }

    // The window holds the picture and the panel beside it. A size the user
    // gives the window (dragging its edge) is added to the picture's, which
    // is drawn again at that size once the dragging stops.
    bool followWindowSize(Clock::time_point now) {
        if (fullscreen_) return false;
        int fbw = 0, fbh = 0;
        glfwGetFramebufferSize(window_.handle(), &fbw, &fbh);
        if (fbw <= 0 || fbh <= 0) return false;
        if (fbw == reqW_ && fbh == reqH_) {
            resizeAt_ = Clock::time_point::max();
            return false;
        }
        if (fbw != seenW_ || fbh != seenH_ || resizeAt_ == Clock::time_point::max()) {
            seenW_ = fbw;
            seenH_ = fbh;
            resizeAt_ = now + std::chrono::milliseconds(150);
            return false;
        }
        if (now < resizeAt_) return false;
        resizeAt_ = Clock::time_point::max();
        int nw = std::max(16, width_ + fbw - reqW_), nh = std::max(16, height_ + fbh - reqH_);
        reqW_ = fbw;
        reqH_ = fbh;
        if (nw != width_ || nh != height_) {
            width_ = nw;
            height_ = nh;
            load(fmt::format("resized to {}x{}", width_, height_).c_str());
        }
        return true;
    }

    // Asks for the window size that holds the picture and the panel.
    void layout() {
        if (fullscreen_) return;
        int maxH = 1000;
        if (GLFWmonitor* m = glfwGetPrimaryMonitor()) {
            int mx, my, mw, mh;
            glfwGetMonitorWorkarea(m, &mx, &my, &mw, &mh);
            if (mh > 200) maxH = mh - 40;
        }
        WindowLayout l = layoutWindow(width_, height_, s_.panelShown, panelW_, panelH_, maxH);
        if (l.windowW != reqW_ || l.windowH != reqH_) {
            reqW_ = l.windowW;
            reqH_ = l.windowH;
            glfwSetWindowSize(window_.handle(), reqW_, reqH_);
            gInput = true;  // draw again at the new size
        }
    }

    std::vector<ViewCommand> panel(int fbw, int fbh) {
        int px, py, pw, ph;
        pictureRect(fbw, fbh, px, py, pw, ph);
        auto asked = drawPanelWindow(s_, float(px + pw), float(fbh), panelW_, panelH_);
        if (fullscreen_) panelW_ = std::min(panelW_, fbw / 2);
        return asked;
    }

    void watchFilesOf(const Plan& plan) {
        std::set<std::string> files = {options_.script};
        for (const auto& p : monitor_.paths()) files.insert(p);  // keep what a broken edit may still need
        for (const auto& prog : plan.programs)
            for (const auto& st : prog.stages) files.insert(st.path);
        for (const auto& t : plan.textures) {
            if (t.source == TextureDecl::Source::File) files.insert(t.path);
            files.insert(t.facePaths.begin(), t.facePaths.end());  // all six faces of a cube map
        }
        for (const auto& m : plan.meshes)
            if (!m.path.empty()) files.insert(m.path);  // OBJ models
        files.erase("");  // a missing file with a stand-in (--stand-ins)
        std::vector<std::string> list(files.begin(), files.end());
        if (list != monitor_.paths()) monitor_.follow(list);
    }

    // Keys, when no text field has the keyboard. True: quit.
    bool keys() {
        ImGuiIO& io = ImGui::GetIO();
        std::vector<int> presses;
        presses.swap(gKeyPresses);
        if (io.WantTextInput) return false;
        for (int key : presses) {  // named as the page's DOM names them, for view/view_keys.h's table
            // GLFW's letter and digit keys are their ASCII capitals and digits, whatever the layout.
            std::string name = key == GLFW_KEY_ESCAPE ? "Escape" : key == GLFW_KEY_SPACE ? " " : key == GLFW_KEY_KP_0 ? "0"
                               : (key >= GLFW_KEY_0 && key <= GLFW_KEY_Z) ? std::string(1, char(key)) : "";
            KeyAction action = keyAction(name);
            if (action == KeyAction::Quit) return true;
            if (applyStateKey(action, s_)) continue;
            if (action == KeyAction::Reload) load("reloaded");
            if (action == KeyAction::Save) save(nextFreeName("glimmer", ".png"), false);
            if (action == KeyAction::Fullscreen) toggleFullscreen();
        }
        return false;
    }

    void toggleFullscreen() {
        GLFWwindow* w = window_.handle();
        if (!fullscreen_) {
            GLFWmonitor* m = glfwGetPrimaryMonitor();
            const GLFWvidmode* mode = m ? glfwGetVideoMode(m) : nullptr;
            if (!mode) return;
            glfwGetWindowPos(w, &savedX_, &savedY_);
            fullscreen_ = true;
            glfwSetWindowMonitor(w, m, 0, 0, mode->width, mode->height, mode->refreshRate);
        } else {
            fullscreen_ = false;
            glfwSetWindowMonitor(w, nullptr, savedX_, savedY_, reqW_, reqH_, 0);
        }
        gInput = true;
    }

    // Drag turns and the wheel zooms, only over the picture (never over the
    // panel, even in the frame the pointer crosses into it) and only for
    // scenes where turning means something (sceneTurns).
    void mouse(int fbw, int fbh) {
        ImGuiIO& io = ImGui::GetIO();
        GLFWwindow* w = window_.handle();
        double x = 0, y = 0;
        glfwGetCursorPos(w, &x, &y);
        int px, py, pw, ph;
        pictureRect(fbw, fbh, px, py, pw, ph);
        bool down = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        bool over = pointerOnPicture(s_, drag_, x, y, down, io.MouseWheel, io.WantCaptureMouse, px, py, pw, ph);
        probe(over && !down, x - px, y - py, pw, ph);
    }

    // The pixel probe (view/viewer_core.h), as a tooltip by the pointer.
    void probe(bool over, double x, double y, int pw, int ph) {
        s_.probeText.clear();
        if (over) core_.probe(x, y, pw, ph);
    }

    // Slices of kSliceMs while the user is at it; once input has stopped
    // for 120 ms, longer ones, so the final picture comes sooner. The numeric
    // health badge reads every target back: after a finished picture, at
    // most twice a second, so dragging a slider stays smooth.
    void renderScene() {
        bool active = Clock::now() - lastInput_ < std::chrono::milliseconds(120);
        core_.draw(active ? sliceMs_ : sliceMs_ * kIdleSliceFactor);
        noteHealth();
    }
    void noteHealth() {
        auto now = Clock::now();
        if (core_.pictureVersion() == healthVersion_ || now - lastHealth_ < std::chrono::milliseconds(500) || !s_.good)
            return;
        healthVersion_ = core_.pictureVersion();
        s_.health = measureHealth(*s_.renderer, s_.good->plan);
        lastHealth_ = now;
        std::string report;
        for (const auto& h : s_.health)
            if (h.bad()) report += formatHealth(h) + "\n";
        if (report != lastReport_) std::cerr << report;  // once per change, for scripts watching stderr
        lastReport_ = report;
    }

    // The panel's text and controls at `scale`, and the overlay with them.
    // Between frames only: ImGui's OpenGL backend remakes its font texture.
    void applyUiScale(float scale, bool remakeTexture = true) {
        setUpFonts(scale);
        if (remakeTexture) {
            ImGui_ImplOpenGL3_DestroyFontsTexture();
            ImGui_ImplOpenGL3_CreateFontsTexture();
        }
        uiScale_ = scale;
        core_.setUiScale(scale);
        std::cerr << fmt::format("glimmer view: ui scale {:g}\n", scale);
    }

    // Follows the monitor's content scale when no --ui-scale was given (GLFW
    // reports a change when the window moves to another monitor).
    void followContentScale() {
        if (!gContentScaleChanged.exchange(false) || options_.uiScale > 0) return;
        float sx = 1, sy = 1;
        glfwGetWindowContentScale(window_.handle(), &sx, &sy);
        const float scale = chooseUiScale(0, sx, sy);
        if (scale != uiScale_) applyUiScale(scale);
    }

    // Runs one command line; true to quit. `onlyAsked`: it only printed
    // (ViewCommand::onlyAsks).
    bool execute(const std::string& line, bool& onlyAsked) {
        std::string error;
        auto c = parseViewCommand(line, error);
        onlyAsked = c && c->onlyAsks();
        if (!c) {
            if (!error.empty()) std::cerr << "glimmer view: " << error << "\n";
            return false;
        }
        return apply(*c);
    }

    bool apply(const ViewCommand& c) {
        std::string said;
        if (core_.apply(c, said)) {  // what only changes what is shown (view/viewer_core.h)
            std::istringstream lines(said);
            for (std::string line; std::getline(lines, line);) std::cerr << "glimmer view: " << line << "\n";
            return false;
        }
        switch (c.kind) {
        case ViewCommand::Kind::Quit: return true;
        case ViewCommand::Kind::Help: std::cerr << helpText(); break;
        case ViewCommand::Kind::Frames: std::cout << core_.frameStats() << std::flush; break;
        case ViewCommand::Kind::Scale: applyUiScale(float(c.value)); break;
        case ViewCommand::Kind::Reload: load("reloaded"); break;
        case ViewCommand::Kind::Save: save(c.name.empty() ? nextFreeName("glimmer", ".png") : c.name, c.unit == -2); break;
        default: break;
        }
        return false;
    }

    // What is shown: the picture (the same pixels `glimmer render` writes for
    // these values and this size) or the inspected target. With the overlay
    // on, the values are burned in, so a handout records its own parameters.
    void save(const std::string& file, bool hardcopy) {
        if (!s_.renderer || !s_.good) {
            std::cerr << "glimmer view: nothing to save yet\n";
            return;
        }
        // A command may have changed values since the last frame, and a
        // frame may be under way: what is saved is the finished picture.
        // Never over one of the script's own files (issue 37: `save
        // bright.frag` turned the shader into a PNG).
        if (std::string refusal = outputRefusal(s_.good->plan, "save", file, "picture"); !refusal.empty()) {
            s_.status = refusal;
            std::cerr << "glimmer view: " << s_.status << "\n";
            return;
        }
        Image img = core_.savedPicture(hardcopy);
        noteHealth();
        if (img.empty()) return;
        std::string why;
        // The name as typed may hold ESC (issue 37): echoed escaped.
        if (writePng(file, img, why)) s_.status = "saved " + sanitizeForTerminal(file, false);
        else s_.status = sanitizeForTerminal(why, false);
        std::cerr << "glimmer view: " << s_.status << "\n";
    }

    const ViewOptions& options_;
    GlfwWindow& window_;
    int width_, height_;  // the picture
    int reqW_, reqH_;     // the window size last asked for
    int seenW_ = 0, seenH_ = 0;
    Clock::time_point resizeAt_ = Clock::time_point::max();
    int panelW_ = 0, panelH_ = 0;
    bool fullscreen_ = false;
    int savedX_ = 0, savedY_ = 0;
    ViewerCore core_;  // the script, its picture and every step on them (view/viewer_core.h)
    ViewerState& s_;   // core_'s
    FileMonitor monitor_;
    Clock::time_point lastHealth_{};
    std::uint64_t healthVersion_ = 0;  // the picture the health badge was measured on
    std::string lastReport_;
    std::set<std::string> printedWarnings_;
    PictureDrag drag_;
    std::unique_ptr<WindowFrame> frame_;  // clears the window; the viewer itself calls no GL
    float uiScale_ = 1.f;
    const double sliceMs_ = sliceBudgetMs();
    Clock::time_point lastInput_{};
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
    if (o.uiScale != 0 && !(o.uiScale >= 0.5 && o.uiScale <= 4)) {
        std::cerr << fmt::format("glimmer: error: --ui-scale {:g} is not between 0.5 and 4\n", o.uiScale);
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
            // A line may hold several commands, as --exec does (issue 39:
            // `set uAdd 2; set uHalfSize 11` on one line was refused).
            for (std::string line; std::getline(std::cin, line);)
                for (const auto& part : splitCommands(line)) queue.push(part);
        }).detach();
    }
    Viewer viewer(o, *window, w, h);
    return viewer.run(queue);
}

}  // namespace glimmer
