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
//   glimmer_view_set(text) -> 1 when "NAME=VALUE" (as --set) applied.
//   glimmer_view_value(name) -> the control's value(s) now, "v1 v2 ...".
//   glimmer_view_control(name) -> "x y w h" of the control's widget in canvas
//       pixels after the last frame ("" when not shown): where a test clicks.
//   glimmer_view_drawn() -> the passes drawn since the last call, "i j ..."
//       by index (a slider reaches only the passes after it).
//   glimmer_view_snapshot() -> 1 when the picture on show (without the panel,
//       with the values box when "Show values" is ticked, as Save writes it)
//       is now in glimmer_pixels; 0 when no script has drawn yet.
//   glimmer_view_command(line) -> one of `glimmer view`'s commands through
//       the same core, and what the window would print for it.
//   glimmer_view_sheet(vary), glimmer_view_sheet_suggestion(): Save sheet
//       (below).
//   glimmer_view_messages() -> the last load's diagnostics for the editor, a
//       line each: severity, file, line, column, message, tab-separated.
//   glimmer_view_files() -> the script and its shader files, a line each.
//   glimmer_view_errors() -> how many errors the panel shows (0: the last load
//       worked).
//   glimmer_view_sets() -> every control's value now, "NAME=V;NAME=V1,V2".
//   glimmer_view_watch() -> the watch: spec, summary, refusal, tab-separated.
// The panel's width is pinned once measured, so messages never widen it.
// Input (web_view_input.cpp) comes from the canvas's own events.
#include <backends/imgui_impl_opengl3.h>
#include <emscripten/emscripten.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <memory>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "sheet/sheet_drawing.h"
#include "pipeline/console.h"
#include "pipeline/prepare_script.h"
#include "gl/window_frame.h"
#include "view/panel.h"
#include "view/view_model.h"
#include "view/view_keys.h"
#include "view/viewer_core.h"
#include "web/page_state.h"

namespace {

using namespace glimmer;

GetProcAddress pageProcs() {
    return [](const char* n) { return glimmer_web::pageContext()->getProcAddress(n); };
}

struct WebViewer {
    // Stand-ins on, as in `glimmer view`: a missing image or model is a
    // warning and a stand-in, not a page that cannot open the script.
    explicit WebViewer(const std::string& path) : script(path), core({path, {}, {}, true, false}, pageProcs()) {}
    std::string script;
    ViewerCore core;
    ViewerState& s = core.state();
    std::unique_ptr<WindowFrame> frame;
    int width = 512, height = 512;  // the picture, as asked
    int panelW = 0, panelH = 0;     // measured from the last frame's panel
    WindowLayout layout;
    std::set<int> drawn;     // the passes drawn since the page last asked (glimmer_view_drawn)
    std::vector<std::string> files;  // the script and its shaders, as the last load named them
    std::string messages;            // the last load's diagnostics, a line each (glimmer_view_messages)
    int keyAsks = 0;         // R and S pressed on the canvas: glimmer_view_frame's answer bits
    bool imguiReady = false;
    // The panel's width, pinned (issue 27): measured once the panel shows a
    // good load and no errors (a few frames, as ImGui settles its fit), at
    // the font size then; a message is then cut at the panel's edge (the
    // page shows it whole, wrapped, and marks it in its editor) instead of
    // widening the canvas and pushing the page's editor aside. 0: not yet.
    int pinnedPanelW = 0;
    float pinnedFontPx = 0;
    int calmFrames = 0;
};
std::unique_ptr<WebViewer> viewer;

// The page's scale: the panel's fonts and the picture shown at it (the
// picture's pixels each S x S of the canvas's, nearest), so a
// devicePixelRatio-2 screen gets a crisp panel at the same size on the
// page, and the projector's presentation mode a large picture and large
// sliders (`scale S`, as the window's command). 1 until the page says.
float gScale = 1.f;
int shownW(const WebViewer& v) { return int(std::lround(v.width * gScale)); }
int shownH(const WebViewer& v) { return int(std::lround(v.height * gScale)); }
WindowLayout layoutOf(const WebViewer& v) { return layoutWindow(shownW(v), shownH(v), true, v.panelW, v.panelH, 8192); }

// Fonts made afresh at `scale` (view/panel.h setUpFonts) and the values box
// with them; between frames only (ImGui's font texture is remade).
void applyScale(float scale) {
    gScale = scale;
    setUpFonts(scale);
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    if (viewer) viewer->core.setUiScale(scale);
}

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

// The files a student edits: the script, then each shader its Programs
// name, once each, in the order they appear.
std::vector<std::string> textFilesOf(const std::string& script, const Plan& plan) {
    std::vector<std::string> files = {script};
    for (const auto& program : plan.programs)
        for (const auto& stage : program.stages)
            if (!stage.path.empty() && std::find(files.begin(), files.end(), stage.path) == files.end())
                files.push_back(stage.path);
    return files;
}

// The script at the asked size (the core keeps every target, for the pass
// inspector, as the desktop does).
int load(WebViewer& v, const std::vector<std::string>& sets, std::ostringstream& out) {
    Diagnostics diags;
    SourceTexts sources;
    Plan plan;
    v.core.setSets(sets);
    bool loaded = v.core.load(v.width, v.height, diags, sources, &plan);
    printDiagnostics(diags, sources, out);
    v.messages = messageLines(diags);
    // The panel shows each message's first line (file:line:col: message),
    // cut at its edge: one line an error, so errors never push the sliders
    // out of a laptop's window (issue 27). The page shows them whole,
    // wrapped, under the canvas, and marks them in its editor.
    for (auto* list : {&v.s.errors, &v.s.warnings})
        for (auto& m : *list) m.text = m.text.substr(0, m.text.find('\n'));
    if (!plan.programs.empty() || v.files.empty()) v.files = textFilesOf(v.script, plan);
    if (!loaded) {
        v.s.status = "keeping the last good picture";
        return std::ifstream(v.script).good() ? 1 : 2;  // 2: the script itself could not be read, as `render` exits
    }
    v.s.status = "loaded";
    return 0;
}

void startImGui(WebViewer& v) {
    if (v.imguiReady) return;
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // nothing written beside the user's files
    // The font files are in the module at the desktop's Debian path (web/CMakeLists.txt).
    setUpFonts(1.f);
    ImGui_ImplOpenGL3_Init("#version 300 es");
    glimmer_web::setUpCanvasInput();
    v.imguiReady = true;
}

// A slice of the frame under way per browser frame (view/viewer_core.h):
// short while the pointer is down or the wheel turns, so a slider dragged
// over a heavy blur keeps its input; longer once it rests.
double gSliceMs = kSliceMs;  // ?slice-ms=0 (whole frames, as before slices) for tools/page-input-latency.mjs

void drawChanged(WebViewer& v) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool active = io.MouseDown[0] || io.MouseWheel != 0;
    v.core.draw(active ? gSliceMs : gSliceMs * kIdleSliceFactor);
    for (int p : v.core.takeDrawnPasses()) v.drawn.insert(p);
}

// The width the panel may take this frame (see WebViewer::pinnedPanelW):
// the pinned one, or before it is measured (a script whose first load
// failed) the width its wrapped text takes, so a long error line cannot
// widen it past that either. A new font size (`scale`) measures again.
void pinPanelWidth(WebViewer& v) {
    const float fontPx = ImGui::GetFontSize();
    if (v.pinnedFontPx != fontPx) {
        v.pinnedFontPx = fontPx;
        v.pinnedPanelW = 0;
        v.calmFrames = 0;
    }
    const float most = v.pinnedPanelW > 0 ? float(v.pinnedPanelW) : fontPx * 30 + ImGui::GetStyle().WindowPadding.x * 2;
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.f, 0.f), ImVec2(most, std::numeric_limits<float>::max()));
}

int applyAsked(WebViewer& v, const std::vector<ViewCommand>& asked) {
    int out = 0;
    for (const auto& c : asked) {
        // What only changes what is shown (the watch's buttons and field
        // among them, issue 39) is the core's, as in the window; what it says
        // goes to the browser's console, as the window's goes to stderr.
        if (std::string said; v.core.apply(c, said)) {
            std::istringstream lines(said);
            for (std::string line; std::getline(lines, line);) std::cout << "glimmer view: " << line << "\n";
            std::cout << std::flush;
            continue;
        }
        if (c.kind == ViewCommand::Kind::Reload) out |= 1;
        if (c.kind != ViewCommand::Kind::Save || !v.s.renderer) continue;
        glimmer_web::pagePicture() = v.core.savedPicture(c.unit == -2);
        out |= c.unit == -2 ? 4 : 2;
    }
    return out;
}

}  // namespace

namespace glimmer_web {
// The picture's rectangle on the canvas, for the input's drag-to-turn.
bool pointerOverPicture(float x, float y) {
    return viewer && x >= 0 && y >= 0 && x < shownW(*viewer) && y < shownH(*viewer);
}
glimmer::ViewerState* viewerState() { return viewer ? &viewer->s : nullptr; }
int shownPictureW() { return viewer ? shownW(*viewer) : 0; }
int shownPictureH() { return viewer ? shownH(*viewer) : 0; }

bool viewerKey(const char* key) {
    if (!viewer || !key) return false;
    // The window's keys (view/view_keys.h); quitting and fullscreen are the browser's.
    KeyAction action = keyAction(key);
    if (applyStateKey(action, viewer->s)) return true;
    if (action == KeyAction::Reload) viewer->keyAsks |= 1;
    else if (action == KeyAction::Save) viewer->keyAsks |= 2;
    else return false;
    return true;
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
        viewer->core.setUiScale(gScale);  // the page's scale outlives a viewer (another script opened)
        viewer->width = width > 0 ? width : 512;
        viewer->height = height > 0 ? height : 512;
    }
    std::string why;
    if (!viewer->frame) viewer->frame = WindowFrame::create(pageProcs(), why);
    if (!viewer->frame) {
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
    ViewerState& s = v.s;
    if (s.playing && seconds > 0 && seconds < 1) s.time += seconds;
    v.layout = layoutOf(v);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(v.layout.windowW), float(v.layout.windowH));
    io.DeltaTime = seconds > 0 && seconds < 1 ? float(seconds) : 1.f / 60.f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    drawChanged(v);
    // The probe, as on the desktop: the values under the pointer, in a tooltip.
    if (!io.WantCaptureMouse && glimmer_web::pointerOverPicture(io.MousePos.x, io.MousePos.y) && !io.MouseDown[0])
        v.core.probe(io.MousePos.x, io.MousePos.y, shownW(v), shownH(v));
    else
        s.probeText.clear();
    pinPanelWidth(v);
    auto asked = drawPanelWindow(s, float(v.layout.panelX), float(v.layout.windowH), v.panelW, v.panelH);
    if (v.pinnedPanelW == 0 && s.good && !s.failed && ++v.calmFrames >= 3) v.pinnedPanelW = v.panelW;
    v.core.drawValues();  // "Show values", over the picture's top left
    for (auto [bit, kind] : {std::pair{1, ViewCommand::Kind::Reload}, std::pair{2, ViewCommand::Kind::Save}})
        if (v.keyAsks & bit) {
            ViewCommand c;
            c.kind = kind;
            asked.push_back(c);
        }
    v.keyAsks = 0;
    ImGui::Render();
    v.frame->begin(v.layout.windowW, v.layout.windowH, 0.12f, 0.12f, 0.14f);
    presentPicture(s, v.layout.windowH, 0, 0, shownW(v), shownH(v));
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    v.core.noteFrame();  // for `frames`, as the window notes its own
    return applyAsked(v, asked);
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_width() {
    return viewer ? layoutOf(*viewer).windowW : 0;
}
EMSCRIPTEN_KEEPALIVE int glimmer_view_height() {
    return viewer ? layoutOf(*viewer).windowH : 0;
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_set(const char* text) {
    if (!viewer || !viewer->s.good || !viewer->s.values || !text) return 0;
    Diagnostics diags;
    bool ok = viewer->s.values->applySet(viewer->s.good->plan, text, diags);
    return ok && !diags.hasErrors() ? 1 : 0;
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_value(const char* name) {
    static std::string text;
    text.clear();
    if (!viewer || !viewer->s.good || !viewer->s.values || !name) return text.c_str();
    const Plan& plan = viewer->s.good->plan;
    for (size_t p = 0; p < plan.programs.size() && text.empty(); ++p)
        for (double x : viewer->s.values->get(int(p), name)) text += (text.empty() ? "" : " ") + fmt::format("{:g}", x);
    return text.c_str();
}

// The watch now, for tests: its spec, its summary and why the last one
// asked for was refused, tab-separated (each empty when there is none).
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_watch() {
    static std::string text;
    text.clear();
    if (viewer) text = viewer->s.watchSpec + "\t" + viewer->s.watchSummary + "\t" + viewer->s.watchError;
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_control(const char* name) {
    static std::string text;
    text.clear();
    if (!viewer || !name) return text.c_str();
    auto it = viewer->s.controlRects.find(name);
    if (it != viewer->s.controlRects.end())
        text = fmt::format("{:g} {:g} {:g} {:g}", it->second[0], it->second[1], it->second[2], it->second[3]);
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_drawn() {
    static std::string text;
    text.clear();
    if (viewer) {
        for (int p : viewer->drawn) text += (text.empty() ? "" : " ") + std::to_string(p);
        viewer->drawn.clear();
    }
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_snapshot() {
    if (!viewer || !viewer->s.renderer) return 0;
    glimmer_web::pagePicture() = viewer->core.savedPicture(false);
    return glimmer_web::pagePicture().empty() ? 0 : 1;
}

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
    if (viewer->core.apply(*c, said)) return said.c_str();
    switch (c->kind) {
    case ViewCommand::Kind::Save:
        if (!viewer->s.renderer || !viewer->s.good) {
            said = "nothing to save yet";
            break;
        }
        glimmer_web::pagePicture() = viewer->core.savedPicture(c->unit == -2);
        said = "saved " + c->name;
        break;
    case ViewCommand::Kind::Frames: said = viewer->core.frameStats(); break;
    case ViewCommand::Kind::Scale:
        applyScale(float(c->value));
        said = fmt::format("ui scale {:g}", c->value);
        break;
    case ViewCommand::Kind::Reload: said = "reload"; break;
    default: said = "error: the page has no '" + std::string(line) + "' (the browser's own zoom, help and tab do that)";
    }
    while (!said.empty() && said.back() == '\n') said.pop_back();
    return said.c_str();
}

// A slice's budget in ms; 0 draws every frame whole (the page before
// slices), for the input-latency benchmark's reference run.
EMSCRIPTEN_KEEPALIVE void glimmer_view_slice_ms(double ms) {
    gSliceMs = ms > 0 ? ms : std::numeric_limits<double>::infinity();
}

// The probe's text now ("" when off or not over the picture): what the
// tooltip by the pointer says.
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_probe() { return viewer ? viewer->s.probeText.c_str() : ""; }

// The page's Save sheet, as `glimmer sheet SCRIPT --vary ...` draws it: the
// cells at the picture's size, the other uniforms at the panel's values
// (named in the title where they differ from the script's). `vary` is one
// or two NAME=V1,V2,... separated by ';'. 0: the sheet is in
// glimmer_pixels; 2: a bad --vary (the message in glimmer_last_output).
EMSCRIPTEN_KEEPALIVE int glimmer_view_sheet(const char* vary) {
    if (!viewer || !viewer->s.good || !viewer->s.renderer) return 2;
    ViewerState& s = viewer->s;
    const Plan& plan = s.good->plan;
    std::vector<SheetAxis> axes;
    for (const std::string& text : glimmer_web::splitSets(vary ? vary : "")) {
        SheetAxis a;
        std::string trimmed = text.substr(text.find_first_not_of(' ') == std::string::npos ? 0 : text.find_first_not_of(' '));
        if (!parseSheetAxis(trimmed, a)) {
            glimmer_web::setLastOutput(fmt::format("glimmer: error: --vary '{}' is not NAME=V1,V2,...\n", text));
            return 2;
        }
        axes.push_back(a);
    }
    if (axes.empty() || axes.size() > 2) {
        glimmer_web::setLastOutput("glimmer: error: a sheet varies one or two uniforms: NAME=V1,V2,...[; NAME=V1,V2,...]\n");
        return 2;
    }
    SheetAxis rows = axes.size() > 1 ? axes[1] : SheetAxis{};
    Diagnostics diags;
    if (!checkSheetValues(plan, *s.values, axes[0], rows, diags)) {
        std::ostringstream out;
        printDiagnostics(diags, s.good->sources, out);
        glimmer_web::setLastOutput(out.str());
        return 2;
    }
    std::string title = std::filesystem::path(viewer->script).filename().string();
    UniformValues defaults(plan);
    for (const auto& c : mergedUniforms(plan, s.splitUniforms)) {
        if (c.name == axes[0].name || c.name == rows.name) continue;
        std::vector<double> now = s.values->get(c.programs.front(), c.name);
        if (now == defaults.get(c.programs.front(), c.name)) continue;
        std::string text;
        for (double x : now) text += (text.empty() ? "" : ",") + fmt::format("{:g}", x);
        title += "   " + c.name + " = " + text;
    }
    glimmer_web::pagePicture() = drawSheet(*s.renderer, plan, *s.values, axes[0], rows, title);
    s.drawAll = true;  // the sheet drew over the view's targets
    glimmer_web::setLastOutput("");
    return 0;
}

// A sheet to suggest: the first slider from its minimum to its maximum in
// three steps ("uAdd=0,2,4"; an int's middle rounded); "" when the script
// has none.
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_sheet_suggestion() {
    static std::string text;
    text.clear();
    if (!viewer || !viewer->s.good) return text.c_str();
    for (const auto& c : mergedUniforms(viewer->s.good->plan))
        if (c.setting->form == UniformSetting::Form::Range) {
            double lo = c.setting->min, hi = c.setting->max, mid = (lo + hi) / 2;
            if (viewer->s.renderer && viewer->s.renderer->uniformKind(c.programs.front(), c.name) == Renderer::UniformKind::Int)
                mid = std::round(mid);
            text = fmt::format("{}={:g},{:g},{:g}", c.name, lo, mid, hi);
            break;
        }
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_messages() { return viewer ? viewer->messages.c_str() : ""; }

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_files() {
    static std::string text;
    text.clear();
    if (viewer)
        for (const auto& f : viewer->files) text += f + "\n";
    return text.c_str();
}

// Every control's value now, as the page's sets: "NAME=V;NAME=V1,V2,..."
// (ranges, checkboxes, colours, vectors; the first Program's value of a
// name). The page keeps it across a reload and gives each back through
// glimmer_view_set (a value a changed script no longer takes is dropped).
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_sets() {
    static std::string text;
    text.clear();
    if (!viewer || !viewer->s.good || !viewer->s.values) return text.c_str();
    std::set<std::string> seen;
    for (const auto& c : mergedUniforms(viewer->s.good->plan)) {
        if (c.setting->form == UniformSetting::Form::Constant || !seen.insert(c.name).second) continue;
        std::string values;
        for (double x : viewer->s.values->get(c.programs.front(), c.name)) values += (values.empty() ? "" : ",") + fmt::format("{}", x);
        if (!values.empty()) text += (text.empty() ? "" : ";") + c.name + "=" + values;
    }
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_errors() { return viewer ? int(viewer->s.errors.size()) : 0; }

}  // extern "C"
