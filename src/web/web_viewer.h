// The page's live viewer between its two files: web_view.cpp (the shell:
// open, frame, commands, what the core asks of the page) and
// web_view_queries.cpp (what the page's script and the tests read and set
// between frames). One viewer at a time, for the page's one canvas.
#pragma once
#include <imgui.h>

#include <cmath>
#include <set>
#include <string>

#include "view/view_model.h"
#include "view/viewer_core.h"
#include "web/page_state.h"

namespace glimmer_web {

using glimmer::ViewerHost;
using glimmer::ViewerCore;
using glimmer::ViewerState;
using glimmer::WindowLayout;

// The page's scale: the panel's fonts and the picture shown at it (the
// picture's pixels each S x S of the canvas's, nearest), so a
// devicePixelRatio-2 screen gets a crisp panel at the same size on the
// page, and the projector's presentation mode a large picture and large
// sliders (`scale S`, as the window's command). 1 until the page says; it
// outlives a viewer (another script opened).
float& pageScale();
glimmer::GetProcAddress pageProcs();

// The page's shell around the viewer core: the canvas's size, the page's
// scale, and what the core asks of the page (ViewerHost): reload and save
// are answered to the page's script (glimmer_view_frame's bits), lines go
// to the browser's console, or into a command's answer while one runs.
struct WebViewer : ViewerHost {
    // Stand-ins on, as in `glimmer view`: a missing image or model is a
    // warning and a stand-in, not a page that cannot open the script.
    explicit WebViewer(const std::string& path)
        : script(path), core({path, {}, {}, true, false, /*oneLineMessages=*/true}, pageProcs()) {}
    std::string script;
    ViewerCore core;
    const ViewerState& s = core.state();
    int width = 512, height = 512;  // the picture, as asked
    std::string messages;    // the last load's diagnostics, a line each (glimmer_view_messages)
    int asks = 0;            // glimmer_view_frame's answer: 1 reload, 2 save, 4 a hardcopy saved
    std::string* answer = nullptr;  // a command's answer being collected (glimmer_view_command)
    double seconds = 0;             // this frame's time step
    bool imguiReady = false;
    // The panel's width, pinned (issue 27): measured once the panel shows a
    // good load and no errors (a few frames, as ImGui settles its fit), at
    // the font size then; a message is then cut at the panel's edge (the
    // page shows it whole, wrapped, and marks it in its editor) instead of
    // widening the canvas and pushing the page's editor aside. 0: not yet.
    int pinnedPanelW = 0;
    // The canvas at most this tall (never below the picture): the page's
    // visible height for it (glimmer_view_fit_height), so a long panel
    // scrolls inside itself and the picture, the verdict and the first
    // error stay in the window (issue 39).
    int fitHeight = 8192;
    float pinnedFontPx = 0;
    int calmFrames = 0;

    int shownW() const { return int(std::lround(width * pageScale())); }
    int shownH() const { return int(std::lround(height * pageScale())); }
    WindowLayout layout() const {
        return glimmer::layoutWindow(shownW(), shownH(), true, core.panelWidth(), core.panelHeight(), fitHeight);
    }

    // ViewerHost (web_view.cpp)
    void platformFrame() override;
    void say(const std::string& line) override;
    void print(const std::string& text, bool toStdout) override;
    void reload() override;
    void save(const std::string& name, bool hardcopy) override;
    void scale(float uiScale) override;
    void quit() override {}  // closing the tab is the browser's
};

// The viewer on show; null before the page opens a script.
WebViewer* liveViewer();

}  // namespace glimmer_web
