// The page's live viewer: `glimmer view` on the page's canvas, a thin shell
// around the desktop's own viewer core (view/viewer_core.h): loading that
// keeps the last good picture and the slider values, drawing the passes a
// slider reaches in slices so the page keeps taking input while a heavy
// blur redraws, hardcopies and the probe are the core's, the same code as
// the window's. The picture is on the left at its own size, the same Dear
// ImGui panel (view/panel.h) on its right, laid out by layoutWindow.
//
// The page drives it (src/web/page/glimmer-page.js); there is no loop in
// here, so the page decides when to draw (requestAnimationFrame) and the
// tests can step it:
//   glimmer_view_open(path, width, height, sets) -> 0 loaded, 1 errors (the
//       last good script, if any, stays on show with the errors in the
//       panel), 2 unreadable. Diagnostics in glimmer_last_output().
//   glimmer_view_frame(seconds) -> one frame: input, panel, the passes that
//       changed, the picture and the panel presented. Returns what the
//       panel's buttons asked for: 1 reload, 2 save (the picture is then in
//       glimmer_pixels), 4 a hardcopy saved at the panel's size (the same).
//   glimmer_view_width(), glimmer_view_height(): the canvas size the layout
//       wants (the page resizes the canvas to it between frames).
//   glimmer_view_command(line) -> one of `glimmer view`'s commands through
//       the same core, and what the window would print for it.
//   the rest (values, controls, the watch, Save sheet, the editor's
//       messages and files): web_view_queries.cpp.
// The panel's width is pinned once measured, so messages never widen it.
// Input (web_view_input.cpp) comes from the canvas's own events.
#include <algorithm>
#include <backends/imgui_impl_opengl3.h>
#include <emscripten/emscripten.h>
#include <imgui.h>

#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "pipeline/console.h"
#include "view/panel.h"
#include "web/page_state.h"
#include "web/web_viewer.h"

namespace {

using namespace glimmer;
using glimmer_web::WebViewer;

// A slice of the frame under way per browser frame (view/viewer_core.h):
// short while the pointer is down or the wheel turns, so a slider dragged
// over a heavy blur keeps its input; longer once it rests.
double gSliceMs = kSliceMs;  // ?slice-ms=0 (whole frames, as before slices) for tools/page-input-latency.mjs

std::unique_ptr<WebViewer> viewer;

// For the page's editor: each diagnostic as one line of tab-separated
// fields, severity, file, line, column, message (tabs and line breaks in a
// message become spaces), so the page marks them on their lines.
std::string messageLines(const Diagnostics& diags) {
    std::string out;
    for (const auto& d : diags.all()) {
        std::string message = d.message;
        for (char& c : message)
            if (c == '\t' || c == '\n' || c == '\r') c = ' ';
        const char* severity = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "note";
        out += fmt::format("{}\t{}\t{}\t{}\t{}\n", severity, d.file, d.loc.line, d.loc.col, message);
    }
    return out;
}

// The script at the asked size (the core keeps every target, for the pass
// inspector, as the desktop does).
int load(WebViewer& v, const std::vector<std::string>& sets, std::ostringstream& out) {
    Diagnostics diags;
    SourceTexts sources;
    v.core.setSets(sets);
    bool loaded = v.core.load(v.width, v.height, diags, sources);
    printDiagnostics(diags, sources, out);
    v.messages = messageLines(diags);
    if (!loaded) {
        v.core.setStatus("keeping the last good picture");
        return std::ifstream(v.script).good() ? 1 : 2;  // 2: the script itself could not be read, as `render` exits
    }
    return 0;
}

void startImGui(WebViewer& v) {
    if (v.imguiReady) return;
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // nothing written beside the user's files
    // The font files are in the module at the desktop's Debian path (web/CMakeLists.txt).
    ImGui_ImplOpenGL3_Init("#version 300 es");
    glimmer_web::setUpCanvasInput();
    v.imguiReady = true;
}

// The width the panel may take this frame (see WebViewer::pinnedPanelW):
// the pinned one, or before it is measured (a script whose first load
// failed) the width its wrapped text takes, so a long error line cannot
// widen it past that either. A new font size (`scale`) measures again.
float panelMaxWidth(WebViewer& v) {
    const float fontPx = kPanelFontPx * v.core.uiScale();
    if (v.pinnedFontPx != fontPx) {
        v.pinnedFontPx = fontPx;
        v.pinnedPanelW = 0;
        v.calmFrames = 0;
    }
    return v.pinnedPanelW > 0 ? float(v.pinnedPanelW) : fontPx * 30 + ImGui::GetStyle().WindowPadding.x * 2;
}

}  // namespace

namespace glimmer_web {

float& pageScale() {
    static float scale = 1.f;
    return scale;
}
GetProcAddress pageProcs() {
    return [](const char* n) { return pageContext()->getProcAddress(n); };
}
WebViewer* liveViewer() { return viewer.get(); }

void WebViewer::platformFrame() {
    const WindowLayout l = layout();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(l.windowW), float(l.windowH));
    io.DeltaTime = seconds > 0 && seconds < 1 ? float(seconds) : 1.f / 60.f;
}
void WebViewer::say(const std::string& line) {
    if (answer) *answer += line + "\n";
    else std::cout << "glimmer view: " << line << "\n" << std::flush;
}
void WebViewer::print(const std::string& text, bool toStdout) {
    if (answer && toStdout) *answer += text;
    else std::cout << text << std::flush;
}
void WebViewer::reload() {  // the page's to do: it has the edited text
    if (answer) *answer += "reload\n";
    else asks |= 1;
}
void WebViewer::save(const std::string& name, bool hardcopy) {
    if (!s.renderer || !s.good) return say("nothing to save yet");
    pagePicture() = core.savedPicture(hardcopy);
    if (answer) say("saved " + name);
    else asks |= hardcopy ? 4 : 2;  // the page downloads glimmer_pixels
}
// Fonts made afresh at `scale` (at the next frame's start) and the picture
// shown at it.
void WebViewer::scale(float uiScale) {
    pageScale() = uiScale;
    core.setUiScale(uiScale);
    if (answer) say(fmt::format("ui scale {:g}", uiScale));
}

// The picture's rectangle on the canvas, for the input's drag-to-turn.
bool pointerOverPicture(float x, float y) {
    return viewer && x >= 0 && y >= 0 && x < viewer->shownW() && y < viewer->shownH();
}
bool viewerPointer(float x, float y, bool down, float wheel, bool captured) {
    return viewer && viewer->core.pointer(x, y, down, wheel, captured, 0, 0, viewer->shownW(), viewer->shownH());
}
void viewerLetGo() {
    if (viewer) viewer->core.letGo();
}
bool viewerTurns() { return viewer && viewer->s.turns; }

bool viewerKey(const char* key) {
    if (!viewer || !key) return false;
    // The window's keys (view/view_keys.h); quitting and fullscreen are the browser's.
    const KeyAction action = viewer->core.key(key);
    return action != KeyAction::None && action != KeyAction::Quit && action != KeyAction::Fullscreen;
}
}  // namespace glimmer_web

extern "C" {

EMSCRIPTEN_KEEPALIVE int glimmer_view_open(const char* path, int width, int height, const char* sets) {
    setVerbosity(Verbosity::Normal);
    std::ostringstream out;
    if (!glimmer_web::pageContext()) {
        glimmer_web::setLastOutput("glimmer: error: this browser cannot make a WebGL 2 context\n");
        return 1;
    }
    std::string asked = path ? path : "";
    // Another script: a fresh viewer (values do not carry across scripts).
    if (!viewer || viewer->script != asked || viewer->width != width || viewer->height != height) {
        bool hadImGui = viewer && viewer->imguiReady;
        viewer.reset();
        viewer = std::make_unique<WebViewer>(asked);
        viewer->imguiReady = hadImGui;
        viewer->core.setUiScale(glimmer_web::pageScale());  // the page's scale outlives a viewer (another script opened)
        viewer->width = width > 0 ? width : 512;
        viewer->height = height > 0 ? height : 512;
    }
    std::string why;
    if (!viewer->core.startFrames(why)) {
        glimmer_web::setLastOutput("glimmer: error: " + why + "\n");
        return 1;
    }
    startImGui(*viewer);
    int code = load(*viewer, glimmer_web::splitSets(sets ? sets : ""), out);
    glimmer_web::setLastOutput(out.str());
    return code;
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_frame(double seconds) {
    if (!viewer || !viewer->imguiReady) return 0;
    WebViewer& v = *viewer;
    if (seconds < 1) v.core.advance(seconds);
    v.seconds = seconds;
    const WindowLayout l = v.layout();
    FrameGeometry g;
    g.windowW = l.windowW;
    g.windowH = l.windowH;
    g.pictureW = v.shownW();
    g.pictureH = v.shownH();
    g.panelX = float(l.panelX);
    g.panelMaxW = panelMaxWidth(v);
    const ImGuiIO& io = ImGui::GetIO();
    g.budgetMs = io.MouseDown[0] || io.MouseWheel != 0 ? gSliceMs : gSliceMs * kIdleSliceFactor;
    v.asks = 0;
    v.core.frame(g, v);
    if (v.pinnedPanelW == 0 && v.s.good && !v.s.failed && ++v.calmFrames >= 3) v.pinnedPanelW = v.core.panelWidth();
    return v.asks;
}

// The height the page has for the canvas; the panel scrolls inside it.
EMSCRIPTEN_KEEPALIVE void glimmer_view_fit_height(int height) {
    if (viewer) viewer->fitHeight = std::clamp(height, 1, 8192);
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_width() { return viewer ? viewer->layout().windowW : 0; }
EMSCRIPTEN_KEEPALIVE int glimmer_view_height() { return viewer ? viewer->layout().windowH : 0; }

// One of `glimmer view`'s commands (view/view_commands.h: set, show,
// values, probe [X Y], split, save, reload, frames), applied by the same
// core as the window's. Returns what the window prints for it, a line each
// without its "glimmer view: " ("" for nothing); `save` puts the picture
// in glimmer_pixels (the page downloads it) and says "saved NAME"; reload
// is the page's to do: "reload" back.
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_command(const char* line) {
    static std::string said;
    said.clear();
    std::string error;
    auto c = parseViewCommand(line ? line : "", error);
    if (!c) {
        said = error.empty() ? "" : "error: " + error;
        return said.c_str();
    }
    if (!viewer) {
        said = "error: no script is open";
        return said.c_str();
    }
    if (c->kind == ViewCommand::Kind::Help || c->kind == ViewCommand::Kind::Quit)
        said = "error: the page has no '" + std::string(line) + "' (the browser's own zoom, help and tab do that)";
    else {
        viewer->answer = &said;  // what the window would print is the answer
        viewer->core.command(*c, *viewer);
        viewer->answer = nullptr;
    }
    while (!said.empty() && said.back() == '\n') said.pop_back();
    return said.c_str();
}

// A slice's budget in ms; 0 draws every frame whole (the page before
// slices), for the input-latency benchmark's reference run.
EMSCRIPTEN_KEEPALIVE void glimmer_view_slice_ms(double ms) {
    gSliceMs = ms > 0 ? ms : std::numeric_limits<double>::infinity();
}

}  // extern "C"
