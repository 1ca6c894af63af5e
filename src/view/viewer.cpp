#include "view/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>

#include <fmt/format.h>

#include "backends/glfw_window.h"
#include "pipeline/options.h"
#include "process/output_guard.h"
#include "view/file_monitor.h"
#include "view/view_model.h"
#include "view/viewer_core.h"
#include "view/wakeups.h"
#include "view/window_fit.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

// While a frame draws and nothing asks for the window, slices follow each
// other without a window frame in between, except to show progress this often.
constexpr auto kProgressEvery = std::chrono::milliseconds(100);

// The window's shell around the viewer core: GLFW's window, events and
// monitor, the file monitor, stderr and files; the frame itself is the
// core's (view/viewer_core.h), the same as the page's.
class Viewer : public ViewerHost {
public:
    Viewer(const ViewOptions& o, GlfwWindow& window, int width, int height)
        : options_(o), window_(window), fit_(window.handle(), width, height),
          core_({o.script, o.includeDirs, o.sets, o.standIns, o.sandbox},
                [&window](const char* n) { return window.getProcAddress(n); }),
          s_(core_.state()) {
        core_.setKeyHint("H hides this panel, F fullscreen, Q quits");
    }

    // Prints errors first, then only the warnings not printed before (a
    // reload does not repeat the seed's warnings every time); the panel
    // keeps both.
    void report() {
        std::string errors, warnings;
        int repeated = 0;
        for (const auto& e : s_.errors) errors += e.text + "\n";
        for (const auto& w : s_.warnings) {
            if (printedWarnings_.insert(w.text).second) warnings += w.text + "\n";
            else ++repeated;
        }
        std::cerr << errors << warnings;
        const size_t counted = warningCount(s_);
        if (!s_.errors.empty() || !warnings.empty())
            std::cerr << fmt::format("{} error{}, {} warning{}{}\n", s_.errors.size(), s_.errors.size() == 1 ? "" : "s",
                                     counted, counted == 1 ? "" : "s",
                                     repeated ? fmt::format(" ({} shown before)", repeated) : "");
    }

    // Loads the script at the current size. On any error the last good
    // script, renderer and values stay; the error is shown and printed.
    void load(const std::string& why) {
        Diagnostics diags;
        SourceTexts sources;
        core_.load(fit_.pictureW(), fit_.pictureH(), diags, sources, nullptr, why);
        if (core_.readFiles() != monitor_.paths()) monitor_.follow(core_.readFiles());
        report();
        say(s_.status);
    }

    int run(CommandQueue& queue) {
        std::string why;
        if (!core_.startFrames(why)) {
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
        core_.setUiScale(chooseUiScale(options_.uiScale, sx, sy));
        gWindowAlive = true;
        FileWaker waker(monitor_.notifyFd());

        auto lastTick = Clock::now();
        int framesLeft = 3;  // ImGui settles its layout over a frame or two
        while (!quit_ && !glfwWindowShouldClose(w)) {
            // Sleep until something happens: input, a command, a file the
            // kernel reports, a resize to settle; a running Timer draws at 50 Hz.
            bool animating = s_.playing && timerUsed();
            const bool busy = core_.drawing();
            if (framesLeft > 0 || busy) glfwPollEvents();
            else if (animating) glfwWaitEventsTimeout(0.02);
            else if (monitor_.busy() || fit_.settling()) glfwWaitEventsTimeout(0.025);
            else if (ImGui::GetIO().WantTextInput) glfwWaitEventsTimeout(0.5);  // the text cursor blinks
            else glfwWaitEvents();
            bool draw = framesLeft > 0 || animating;
            if (framesLeft > 0) --framesLeft;
            auto now = Clock::now();
            if (gInput.exchange(false)) {
                framesLeft = 3;
                draw = true;
                lastInput_ = now;
            }
            core_.advance(std::chrono::duration<double>(now - lastTick).count());
            lastTick = now;

            followContentScale();
            bool resized = false;
            draw |= fit_.follow(now, resized);
            if (resized) load(fmt::format("resized to {}x{}", fit_.pictureW(), fit_.pictureH()));
            auto changed = monitor_.poll(now);
            if (!changed.empty()) {
                load(fmt::format("reloaded after a change to {}", changed.front()));
                draw = true;
            }
            for (const auto& line : queue.take()) {
                std::string error;
                auto c = parseViewCommand(line, error);
                if (c) core_.command(*c, *this);
                else if (!error.empty()) say(error);
                draw = true;
                // A command that only asks does not make the user busy (the
                // benchmark's `frames` must not shorten the slices it measures).
                if (!c || !c->onlyAsks()) lastInput_ = now;
            }
            if (quit_) {
                core_.noteHealth(*this, true);  // a script that quits at once still hears of a NaN
                break;
            }
            if (!draw && busy) {
                // Nothing asked for the window: draw more of the frame, and
                // show how far it got now and then.
                if (Clock::now() - core_.lastFrameShown() < kProgressEvery) {
                    core_.draw(sliceNow());
                    core_.noteHealth(*this);
                    if (core_.drawing()) continue;
                }
                draw = true;  // progress to show, or the finished picture
            }
            if (!draw) continue;

            FrameGeometry g;
            glfwGetFramebufferSize(w, &g.windowW, &g.windowH);
            fit_.pictureRect(g.windowW, g.windowH, s_.panelShown, panelW_, g.pictureX, g.pictureY, g.pictureW, g.pictureH);
            g.panelX = float(g.pictureX + g.pictureW);
            g.budgetMs = sliceNow();
            core_.frame(g, *this);
            glfwSwapBuffers(w);
            panelW_ = core_.panelWidth();
            panelH_ = core_.panelHeight();
            if (fit_.fullscreen()) panelW_ = std::min(panelW_, g.windowW / 2);
            fit_.layout(s_.panelShown, panelW_, panelH_);
        }
        gWindowAlive = false;
        core_.releaseGl();  // while the context is still current
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        return kExitOk;
    }

    // ViewerHost: what the core asks of the window.
    void platformFrame() override { ImGui_ImplGlfw_NewFrame(); }
    void input() override {
        keys();
        mouse();
    }
    void say(const std::string& line) override { std::cerr << "glimmer view: " << line << "\n"; }
    void print(const std::string& text, bool toStdout) override { (toStdout ? std::cout : std::cerr) << text << std::flush; }
    void reload() override { load("reloaded"); }
    void scale(float s) override { core_.setUiScale(s); }
    void quit() override { quit_ = true; }

    // What is shown: the picture (the same pixels `glimmer render` writes for
    // these values and this size) or the inspected target. With the overlay
    // on, the values are burned in, so a handout records its own parameters.
    void save(const std::string& name, bool hardcopy) override {
        const std::string file = name.empty() ? nextFreeName("glimmer", ".png") : name;
        if (!s_.renderer || !s_.good) {
            say("nothing to save yet");
            return;
        }
        // Never over one of the script's own files (issue 37: `save
        // bright.frag` turned the shader into a PNG).
        if (std::string refusal = outputRefusal(s_.good->plan, "save", file, "picture"); !refusal.empty()) {
            core_.setStatus(refusal);
            say(refusal);
            return;
        }
        // A frame may be under way: what is saved is the finished picture.
        Image img = core_.savedPicture(hardcopy);
        core_.noteHealth(*this, true);
        if (img.empty()) return;
        std::string why;
        // The name as typed may hold ESC (issue 37): echoed escaped.
        core_.setStatus(writePng(file, img, why) ? "saved " + sanitizeForTerminal(file, false)
                                                  : sanitizeForTerminal(why, false));
        say(s_.status);
    }

private:
    bool timerUsed() const {
        if (!s_.renderer || !s_.good) return false;
        for (size_t p = 0; p < s_.good->plan.programs.size(); ++p)
            if (s_.renderer->usesTimer(int(p))) return true;
        return false;
    }

    // Slices of kSliceMs while the user is at it; once input has stopped
    // for 120 ms, longer ones, so the final picture comes sooner.
    double sliceNow() const {
        const bool active = Clock::now() - lastInput_ < std::chrono::milliseconds(120);
        return active ? sliceMs_ : sliceMs_ * kIdleSliceFactor;
    }

    // Keys, when no text field has the keyboard: the core's, named as the
    // page's DOM names them (view/view_keys.h), and fullscreen, the window's.
    void keys() {
        std::vector<int> presses;
        presses.swap(gKeyPresses);
        if (ImGui::GetIO().WantTextInput) return;
        for (int key : presses) {
            // GLFW's letter and digit keys are their ASCII capitals and digits, whatever the layout.
            std::string name = key == GLFW_KEY_ESCAPE ? "Escape" : key == GLFW_KEY_SPACE ? " " : key == GLFW_KEY_KP_0 ? "0"
                               : (key >= GLFW_KEY_0 && key <= GLFW_KEY_Z) ? std::string(1, char(key)) : "";
            if (core_.key(name) == KeyAction::Fullscreen) fit_.toggleFullscreen();
        }
    }

    // Drag turns and the wheel zooms, only over the picture (never over the
    // panel, even in the frame the pointer crosses into it) and only for
    // scenes where turning means something (sceneTurns).
    void mouse() {
        GLFWwindow* w = window_.handle();
        double x = 0, y = 0;
        glfwGetCursorPos(w, &x, &y);
        int fbw = 0, fbh = 0, px, py, pw, ph;
        glfwGetFramebufferSize(w, &fbw, &fbh);
        fit_.pictureRect(fbw, fbh, s_.panelShown, panelW_, px, py, pw, ph);
        const ImGuiIO& io = ImGui::GetIO();
        core_.pointer(x, y, glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS, io.MouseWheel,
                      io.WantCaptureMouse, px, py, pw, ph);
    }

    // Follows the monitor's content scale when no --ui-scale was given (GLFW
    // reports a change when the window moves to another monitor).
    void followContentScale() {
        if (!gContentScaleChanged.exchange(false) || options_.uiScale > 0) return;
        float sx = 1, sy = 1;
        glfwGetWindowContentScale(window_.handle(), &sx, &sy);
        core_.setUiScale(chooseUiScale(0, sx, sy));
    }

    const ViewOptions& options_;
    GlfwWindow& window_;
    WindowFit fit_;  // the window's size and the picture's (view/window_fit.h)
    int panelW_ = 0, panelH_ = 0;
    bool quit_ = false;
    ViewerCore core_;       // the script, its picture, the frame (view/viewer_core.h)
    const ViewerState& s_;  // core_'s, read-only
    FileMonitor monitor_;
    std::set<std::string> printedWarnings_;
    const double sliceMs_ = sliceBudgetMs();
    Clock::time_point lastInput_{};
};

}  // namespace

int runView(const ViewOptions& o) {
    int w = 600, h = 600;
    if (int refused = checkViewOptions(o, w, h)) return refused;
    std::string why;
    auto window = GlfwWindow::open(w, h, "Glimmer - " + o.script, why);
    if (!window) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    CommandQueue queue;
    queue.start(o.exec, o.readStdin);
    Viewer viewer(o, *window, w, h);
    return viewer.run(queue);
}

}  // namespace glimmer
