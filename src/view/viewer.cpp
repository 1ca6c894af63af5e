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
#include "driver/options.h"
#include "driver/prepare_script.h"
#include "gl/ui_texture.h"
#include "gl/window_frame.h"
#include "image/ttf_text.h"
#include "plan/dependencies.h"
#include "view/file_watch.h"
#include "view/panel.h"
#include "view/view_model.h"
#include "view/wakeups.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

// A slice of a heavy frame draws for about this long between two window
// frames: with the window's own ~10 ms on llvmpipe a frame stays near 35 ms
// while a slider is dragged (the goal is a p95 under 50 ms), and the bands
// stay tall enough that their set-up costs little (docs/PERFORMANCE.md).
constexpr double kSliceMs = 18;
// While a frame draws and nothing asks for the window, slices follow each
// other without a window frame in between, except to show progress this often.
constexpr auto kProgressEvery = std::chrono::milliseconds(100);
constexpr double kIdleSliceFactor = 5;
constexpr int kOverlayAt = 8;  // the "Show values" box's top left, in the picture and in the window

// The slice budget: kSliceMs, or $GLIMMER_SLICE_MS for benchmarks
// (tools/bench-viewer.sh), where 0 draws every frame whole, as before slices.
double sliceBudgetMs() {
    const char* e = std::getenv("GLIMMER_SLICE_MS");
    if (!e || !*e) return kSliceMs;
    char* end = nullptr;
    double v = std::strtod(e, &end);
    if (end == e || *end || !(v >= 0) || v > 1e6) return kSliceMs;
    return v == 0 ? std::numeric_limits<double>::infinity() : v;
}

class Viewer {
public:
    Viewer(const ViewOptions& o, GlfwWindow& window, int width, int height)
        : options_(o), window_(window), width_(width), height_(height), reqW_(width), reqH_(height) {
        s_.keyHint = "H hides this panel, F fullscreen, Q quits";
    }

    // The script at w x h, parsed, planned and prepared on a renderer of its
    // own. False (with diagnostics) when anything failed; `renderer` is then null.
    bool prepareAt(int w, int h, LoadedScript& next, std::unique_ptr<Renderer>& renderer, Diagnostics& diags) {
        ScriptRequest request;
        request.script = options_.script;
        request.plan.includeDirs = options_.includeDirs;
        request.plan.standIns = options_.standIns;
        request.plan.sandbox = options_.sandbox;
        request.plan.width = w;
        request.plan.height = h;
        // Every target can be looked at in the pass inspector, so every pass
        // that draws into one runs, read by a later pass or not.
        for (int unit = 0; unit < 32; ++unit) request.plan.keepTargets.insert(unit);
        renderer = prepareScript(request, [&](const char* n) { return window_.getProcAddress(n); }, diags, next);
        return renderer != nullptr;
    }

    // Prints errors first, then only the warnings not printed before (a
    // reload does not repeat the seed's warnings every time), and keeps both
    // for the panel.
    void report(const Diagnostics& diags, const SourceTexts& sources) {
        keepMessages(s_, diags, sources);
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
        LoadedScript next;
        std::unique_ptr<Renderer> renderer;
        prepareAt(width_, height_, next, renderer, diags);
        watchFilesOf(next.plan);
        report(diags, next.sources);
        if (!renderer) {
            if (s_.errors.empty()) s_.errors.push_back({"the script could not be loaded", options_.script});
            s_.failed = true;
            s_.status = fmt::format("{} failed; keeping the last good picture", why);
            std::cerr << "glimmer view: " << s_.status << "\n";
            return;
        }
        adoptScript(s_, std::move(next), std::move(renderer), options_.sets, diags);
        drawing_.reset();  // its passes belong to the old plan
        firstFrame_ = true;
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
        overlayTexture_ = UiTexture::create([&](const char* n) { return window_.getProcAddress(n); }, why);
        applyUiScale(chooseUiScale(options_.uiScale, sx, sy), false);
        gWindowAlive = true;
        FileWaker waker(watch_.notifyFd());

        auto lastTick = Clock::now();
        bool quit = false;
        int framesLeft = 3;  // ImGui settles its layout over a frame or two
        while (!quit && !glfwWindowShouldClose(w)) {
            // Sleep until something happens: input, a command, a file the
            // kernel reports, a resize to settle; a running Timer draws at 50 Hz.
            ImGuiIO& io = ImGui::GetIO();
            bool animating = s_.playing && timerUsed();
            const bool busy = drawing_.has_value();
            if (framesLeft > 0 || busy) glfwPollEvents();
            else if (animating) glfwWaitEventsTimeout(0.02);
            else if (watch_.busy() || resizeAt_ != Clock::time_point::max()) glfwWaitEventsTimeout(0.025);
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
            auto changed = watch_.poll(now);
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
                if (Clock::now() - lastUiFrame_ < kProgressEvery) {
                    renderScene();
                    if (drawing_) continue;
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
            overlay();
            ImGui::Render();
            frame_->begin(fbw, fbh, 0.12f, 0.12f, 0.14f);
            presentPicture(fbw, fbh);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            glfwSwapBuffers(w);
            noteFrame();
            for (const auto& c : asked) quit |= apply(c);
            layout();
        }
        gWindowAlive = false;
        s_.renderer.reset();
        overlayTexture_.reset();  // while the context is still current
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

    // "Show values": one line per control, over a dark box, at the
    // picture's top left, in DejaVu: the same layer a saved PNG gets.
    void overlay() {
        if (!s_.showValues) return;
        const Image& layer = overlayLayer();
        if (layer.empty() || !overlayTexture_) return;
        if (overlayUploaded_ != overlayMadeFor_) {
            overlayId_ = overlayTexture_->upload(layer);
            overlayUploaded_ = overlayMadeFor_;
        }
        if (!overlayId_) return;
        // The picture's top left is the window's: the same offset as in a saved PNG.
        ImGui::GetForegroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(overlayId_)),
                                                 ImVec2(kOverlayAt, kOverlayAt),
                                                 ImVec2(float(kOverlayAt + layer.width), float(kOverlayAt + layer.height)));
    }

    // The "Show values" overlay as a layer (image/ttf_text.h labelLayer):
    // DejaVu at the panel's scale, remade only when its text changes. The
    // window draws it over the picture and a save lays it over the PNG, so
    // both carry the same pixels in the same place.
    const Image& overlayLayer() {
        std::string text = overlayText(s_);
        std::string key = fmt::format("{}|{}", overlayPx_, text);
        if (key != overlayMadeFor_) {
            overlay_ = text.empty() ? Image{} : labelLayer(text, overlayPx_);
            overlayMadeFor_ = key;
        }
        return overlay_;
    }

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
        files.erase("");  // a missing file with a stand-in (--stand-ins)
        std::vector<std::string> list(files.begin(), files.end());
        if (list != watch_.paths()) watch_.watch(list);
    }

    // Keys, when no text field has the keyboard. True: quit.
    bool keys() {
        ImGuiIO& io = ImGui::GetIO();
        std::vector<int> presses;
        presses.swap(gKeyPresses);
        if (io.WantTextInput) return false;
        auto pressed = [&](int key) { return std::find(presses.begin(), presses.end(), key) != presses.end(); };
        if (pressed(GLFW_KEY_Q) || pressed(GLFW_KEY_ESCAPE)) return true;
        if (pressed(GLFW_KEY_SPACE)) s_.playing = !s_.playing;
        if (pressed(GLFW_KEY_H)) s_.panelShown = !s_.panelShown;
        if (pressed(GLFW_KEY_R)) load("reloaded");
        if (pressed(GLFW_KEY_0) || pressed(GLFW_KEY_KP_0)) resetView(s_);
        if (pressed(GLFW_KEY_S)) save(nextFreeName("glimmer", ".png"), false);
        if (pressed(GLFW_KEY_F)) toggleFullscreen();
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

    // The pixel probe: the float value of every channel of the shown target
    // under the pointer, read back once per new picture.
    void probe(bool over, double x, double y, int pw, int ph) {
        s_.probeText.clear();
        if (!s_.probe || !over || !s_.renderer || s_.compare) return;
        if (probeVersion_ != pictureVersion_ || probeTexture_ != s_.shownTexture) {
            probeImage_ = s_.shownTexture < 0 ? s_.renderer->readScreen() : s_.renderer->readTextureFloat(s_.shownTexture);
            probeVersion_ = pictureVersion_;
            probeTexture_ = s_.shownTexture;
        }
        const Image& img = probeImage_;
        if (img.empty()) return;
        double scale = std::min(double(pw) / img.width, double(ph) / img.height);
        double ox = (pw - img.width * scale) / 2, oy = (ph - img.height * scale) / 2;
        int ix = int(std::floor((x - ox) / scale)), iy = int(std::floor((y - oy) / scale));
        if (ix < 0 || iy < 0 || ix >= img.width || iy >= img.height) return;
        size_t i = (size_t(iy) * size_t(img.width) + size_t(ix)) * 4;
        float v[4];
        for (int c = 0; c < 4; ++c) v[c] = img.type == Image::Type::F32 ? img.f32[i + size_t(c)] : img.u8[i + size_t(c)] / 255.f;
        s_.probeText = fmt::format("({}, {}) of {}: r {:.4g}  g {:.4g}  b {:.4g}  a {:.4g}", ix, iy,
                                   s_.shownTexture < 0 ? std::string("screen") : fmt::format("texture {}", s_.shownTexture),
                                   v[0], v[1], v[2], v[3]);
        ImGui::BeginTooltip();
        ImGui::TextUnformatted(s_.probeText.c_str());
        ImGui::EndTooltip();
    }

    // Slices of kSliceMs while the user is at it; once input has stopped
    // for 120 ms, longer ones, so the final picture comes sooner (fewer
    // bands and window frames between them).
    void renderScene() {
        // A script's first picture is drawn whole: until it is, its targets
        // and screen hold nothing to show, and the last picture is gone
        // with the old renderer (a reload is one pause, not a drag).
        if (firstFrame_) {
            renderScene(std::numeric_limits<double>::infinity());
            firstFrame_ = drawing_.has_value();
            return;
        }
        bool active = Clock::now() - lastInput_ < std::chrono::milliseconds(120);
        renderScene(active ? sliceMs_ : sliceMs_ * kIdleSliceFactor);
    }
    // Starts a frame of the passes that changed since the last one started:
    // all after a load, the ones reading a changed Program's uniforms, the
    // ones reading Timer while time runs. A change while a frame is under
    // way replaces it, and the new frame also draws what the old one had not
    // finished (the stale work is dropped, never half kept). Then draws
    // about `budgetMs` of the frame in bands (gl/renderer_sliced.cpp), so a
    // heavy pass never holds the window; the picture counts as drawn once
    // the frame finishes, bit-identical to one whole render.
    void renderScene(double budgetMs) {
        if (!s_.renderer || !s_.good) return;
        const Plan& plan = s_.good->plan;
        Change change = changeSinceDrawn(s_, false);
        // Time alone never replaces a frame under way: a heavy animated scene
        // would otherwise restart every window frame and never finish one.
        if (s_.time != s_.drawnTime && (!drawing_ || !change.programs.empty() || change.screen || change.everything))
            change = changeSinceDrawn(s_, true);
        s_.sceneMoved = false;
        std::vector<bool> only = passesToRun(plan, change);
        bool any = false;
        for (bool b : only) any |= b;
        if (any) {
            if (drawing_) {
                std::vector<bool> left = drawing_->unfinished();
                for (size_t p = 0; p < only.size() && p < left.size(); ++p) only[p] = only[p] || left[p];
            }
            drawing_.emplace(s_.renderer->startFrame(*s_.values, s_.time, std::move(only)));
            drawingSince_ = Clock::now();
            slices_ = 0;  // the slices of this frame only
            s_.drawnWith = s_.values;
            s_.drawnTime = s_.time;
            s_.drawAll = false;
        }
        if (!drawing_) return;
        ++slices_;
        if (!s_.renderer->renderSlice(*drawing_, budgetMs)) {
            s_.drawing = float(s_.renderer->progress(*drawing_));
            return;
        }
        s_.drawing = -1;
        s_.lastTimings = drawing_->timings;
        s_.lastFrameMs = 0;
        for (const auto& t : s_.lastTimings) s_.lastFrameMs += t.ms;
        lastPictureMs_ = std::chrono::duration<double, std::milli>(Clock::now() - drawingSince_).count();
        lastPictureSlices_ = slices_;
        drawing_.reset();
        ++pictureVersion_;
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

    // The panel's text and controls at `scale`, and the overlay with them.
    // Between frames only: ImGui's OpenGL backend remakes its font texture.
    void applyUiScale(float scale, bool remakeTexture = true) {
        setUpFonts(scale);
        if (remakeTexture) {
            ImGui_ImplOpenGL3_DestroyFontsTexture();
            ImGui_ImplOpenGL3_CreateFontsTexture();
        }
        uiScale_ = scale;
        overlayPx_ = 15.f * scale;  // legible from the back of a room at --ui-scale 2
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

    // The time since the last window frame, while the window is busy (a
    // pause of a second or more is idle time, not a slow frame).
    void noteFrame() {
        auto now = Clock::now();
        double ms = std::chrono::duration<double, std::milli>(now - lastUiFrame_).count();
        if (ms < 1000 && frameIntervals_.size() < 1000000) frameIntervals_.push_back(ms);
        lastUiFrame_ = now;
    }

    // The `frames` command: how long the window took between frames since
    // the last `frames` (what a drag feels like), and how long the last
    // picture took to finish after its last change. tools/bench-viewer.sh reads it.
    void printFrameStats() {
        std::vector<double> d = frameIntervals_;
        frameIntervals_.clear();
        std::sort(d.begin(), d.end());
        auto at = [&](double q) { return d.empty() ? 0.0 : d[std::min(d.size() - 1, size_t(q * double(d.size())))]; };
        std::cout << fmt::format("frames: {} drawn, median {:.1f} ms, p95 {:.1f} ms, max {:.1f} ms; "
                                 "last picture {:.1f} ms after its last change ({:.1f} ms drawing, {} slice{}){}\n",
                                 d.size(), at(0.5), at(0.95), d.empty() ? 0.0 : d.back(), lastPictureMs_,
                                 s_.lastFrameMs, lastPictureSlices_, lastPictureSlices_ == 1 ? "" : "s",
                                 drawing_ ? "; a picture is being drawn" : "");
        std::cout.flush();
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
        switch (c.kind) {
        case ViewCommand::Kind::Quit: return true;
        case ViewCommand::Kind::Help: std::cerr << helpText(); break;
        case ViewCommand::Kind::Frames: printFrameStats(); break;
        case ViewCommand::Kind::Scale: applyUiScale(float(c.value)); break;
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
        case ViewCommand::Kind::Save: save(c.name.empty() ? nextFreeName("glimmer", ".png") : c.name, c.unit == -2); break;
        case ViewCommand::Kind::Show: textureOnUnit("show", c.unit, s_.shownTexture); break;
        case ViewCommand::Kind::Values: s_.showValues = c.on; break;
        case ViewCommand::Kind::Probe:
            if (!c.report) s_.probe = c.on;
            else if (!s_.probe) std::cerr << "glimmer view: probe: off (probe on turns it on)\n";
            else if (s_.probeText.empty()) std::cerr << "glimmer view: probe: the pointer is not over the picture\n";
            else std::cerr << "glimmer view: probe " << s_.probeText << "\n";
            break;
        case ViewCommand::Kind::Split:
            if (c.on && textureOnUnit("split", c.unit, s_.compareLeft) && textureOnUnit("split", c.right, s_.compareRight))
                s_.compare = true;
            else if (!c.on) s_.compare = false;
            break;
        }
        return false;
    }

    // The texture on a texture unit (the screen for -1) into `texture`;
    // false, with a message, when no target is on that unit.
    bool textureOnUnit(const char* command, int unit, int& texture) {
        if (unit < 0) return texture = -1, true;
        if (s_.good && s_.good->plan.finalUnits.count(unit)) return texture = s_.good->plan.finalUnits.at(unit), true;
        std::cerr << "glimmer view: " << command << ": no texture on unit " << unit << "\n";
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
        Image img;
        if (hardcopy) {
            img = renderAtSize(s_.hardcopy[0], s_.hardcopy[1]);
        } else {
            // A command may have changed values since the last frame, and a
            // frame may be under way: what is saved is the finished picture.
            renderScene(std::numeric_limits<double>::infinity());
            img = s_.shownTexture < 0 ? s_.renderer->readScreen() : s_.renderer->readTexture(s_.shownTexture);
        }
        if (img.empty()) return;
        if (s_.showValues) layOver(img, overlayLayer(), kOverlayAt, kOverlayAt);
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
        r->setSceneTransform(sceneMatrix(s_));
        r->render(v, s_.time);
        return r->readScreen();
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
    ViewerState s_;
    FileWatch watch_;
    Clock::time_point lastHealth_{};
    std::string lastReport_;
    std::set<std::string> printedWarnings_;
    PictureDrag drag_;
    std::uint64_t pictureVersion_ = 0, probeVersion_ = ~0ull;
    int probeTexture_ = -2;
    Image probeImage_;
    std::unique_ptr<WindowFrame> frame_;  // clears the window; the viewer itself calls no GL
    std::unique_ptr<UiTexture> overlayTexture_;  // the overlay layer, for ImGui to draw
    Image overlay_;
    std::string overlayMadeFor_, overlayUploaded_;
    unsigned overlayId_ = 0;
    float overlayPx_ = 15.f;
    float uiScale_ = 1.f;
    // The frame being drawn a slice at a time (none when the picture is done).
    std::optional<SlicedFrame> drawing_;
    const double sliceMs_ = sliceBudgetMs();
    bool firstFrame_ = true;  // the next frame is a new renderer's first: drawn whole
    Clock::time_point drawingSince_{}, lastUiFrame_{}, lastInput_{};
    int slices_ = 0, lastPictureSlices_ = 0;
    double lastPictureMs_ = 0;
    std::vector<double> frameIntervals_;  // ms between window frames while busy, for `frames`
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
            for (std::string line; std::getline(std::cin, line);) queue.push(line);
        }).detach();
    }
    Viewer viewer(o, *window, w, h);
    return viewer.run(queue);
}

}  // namespace glimmer
