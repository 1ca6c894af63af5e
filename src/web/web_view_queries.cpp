// What the page's script and its tests read and set on the live viewer
// between frames (web_view.cpp is the shell that draws them):
//   glimmer_view_set(text) -> 1 when "NAME=VALUE" (as --set) applied.
//   glimmer_view_value(name) -> the control's value(s) now, "v1 v2 ...".
//   glimmer_view_control(name) -> "x y w h" of the control's widget in canvas
//       pixels after the last frame ("" when not shown): where a test clicks.
//   glimmer_view_drawn() -> the passes drawn since the last call, "i j ..."
//       by index (a slider reaches only the passes after it).
//   glimmer_view_snapshot() -> 1 when the picture on show (without the panel,
//       with the values box when "Show values" is ticked, as Save writes it)
//       is now in glimmer_pixels; 0 when no script has drawn yet.
//   glimmer_view_sheet(vary), glimmer_view_sheet_suggestion(): Save sheet
//       (below).
//   glimmer_view_messages() -> the last load's diagnostics for the editor, a
//       line each: severity, file, line, column, message, tab-separated.
//   glimmer_view_files() -> the script and its shader files, a line each.
//   glimmer_view_errors() -> how many errors the panel shows (0: the last load
//       worked).
//   glimmer_view_sets() -> every control's value now, "NAME=V;NAME=V1,V2".
//   glimmer_view_watch() -> the watch: spec, summary, refusal, tab-separated.
#include <emscripten/emscripten.h>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "pipeline/console.h"
#include "sheet/sheet_request.h"
#include "web/page_state.h"
#include "web/web_viewer.h"

using namespace glimmer;
using glimmer_web::liveViewer;

extern "C" {

EMSCRIPTEN_KEEPALIVE int glimmer_view_set(const char* text) {
    Diagnostics diags;
    return liveViewer() && text && liveViewer()->core.set(text, diags) ? 1 : 0;
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_value(const char* name) {
    static std::string text;
    text.clear();
    if (!liveViewer() || !liveViewer()->s.good || !liveViewer()->s.values || !name) return text.c_str();
    const Plan& plan = liveViewer()->s.good->plan;
    for (size_t p = 0; p < plan.programs.size() && text.empty(); ++p)
        for (double x : liveViewer()->s.values->get(int(p), name)) text += (text.empty() ? "" : " ") + fmt::format("{:g}", x);
    return text.c_str();
}

// The watch now, for tests: its spec, its summary and why the last one
// asked for was refused, tab-separated (each empty when there is none).
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_watch() {
    static std::string text;
    text.clear();
    if (liveViewer()) text = liveViewer()->s.watchSpec + "\t" + liveViewer()->s.watchSummary + "\t" + liveViewer()->s.watchError;
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_control(const char* name) {
    static std::string text;
    text.clear();
    if (!liveViewer() || !name) return text.c_str();
    auto it = liveViewer()->s.controlRects.find(name);
    if (it != liveViewer()->s.controlRects.end())
        text = fmt::format("{:g} {:g} {:g} {:g}", it->second[0], it->second[1], it->second[2], it->second[3]);
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_drawn() {
    static std::string text;
    text.clear();
    if (liveViewer())  // the core keeps them until asked
        for (int p : liveViewer()->core.takeDrawnPasses()) text += (text.empty() ? "" : " ") + std::to_string(p);
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_snapshot() {
    if (!liveViewer() || !liveViewer()->s.renderer) return 0;
    glimmer_web::pagePicture() = liveViewer()->core.savedPicture(false);
    return glimmer_web::pagePicture().empty() ? 0 : 1;
}

// The probe's text now ("" when off or not over the picture): what the
// tooltip by the pointer says.
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_probe() { return liveViewer() ? liveViewer()->s.probeText.c_str() : ""; }

// The page's Save sheet, as `glimmer sheet SCRIPT --vary ...` draws it: the
// cells at the picture's size, the other uniforms at the panel's values
// (named in the title where they differ from the script's). `vary` is one
// or two NAME=V1,V2,... separated by ';'. 0: the sheet is in
// glimmer_pixels; 2: a bad --vary (the message in glimmer_last_output).
EMSCRIPTEN_KEEPALIVE int glimmer_view_sheet(const char* vary) {
    if (!liveViewer() || !liveViewer()->s.good || !liveViewer()->s.renderer) return 2;
    const ViewerState& s = liveViewer()->s;
    SheetRequest request;
    std::string usage;
    Diagnostics diags;
    const std::string scriptName = std::filesystem::path(liveViewer()->script).filename().string();
    if (!makeSheetRequest(glimmer_web::splitSets(vary ? vary : ""), scriptName, s.good->plan, *s.values, request,
                          usage, diags)) {
        std::ostringstream out;
        if (!usage.empty()) out << "glimmer: error: " << usage << "\n";
        printDiagnostics(diags, s.good->sources, out);
        glimmer_web::setLastOutput(out.str());
        return 2;
    }
    glimmer_web::pagePicture() = liveViewer()->core.sheet(request);
    glimmer_web::setLastOutput("");
    return 0;
}

// A sheet to suggest: the first slider from its minimum to its maximum in
// three steps ("uAdd=0,2,4"; an int's middle rounded); "" when the script
// has none.
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_sheet_suggestion() {
    static std::string text;
    text.clear();
    if (!liveViewer() || !liveViewer()->s.good) return text.c_str();
    for (const auto& c : mergedUniforms(liveViewer()->s.good->plan))
        if (c.setting->form == UniformSetting::Form::Range) {
            double lo = c.setting->min, hi = c.setting->max, mid = (lo + hi) / 2;
            if (liveViewer()->s.renderer && liveViewer()->s.renderer->uniformKind(c.programs.front(), c.name) == Renderer::UniformKind::Int)
                mid = std::round(mid);
            text = fmt::format("{}={:g},{:g},{:g}", c.name, lo, mid, hi);
            break;
        }
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_messages() { return liveViewer() ? liveViewer()->messages.c_str() : ""; }

EMSCRIPTEN_KEEPALIVE const char* glimmer_view_files() {
    static std::string text;
    text.clear();
    if (liveViewer())
        for (const auto& f : liveViewer()->core.scriptFiles()) text += f + "\n";
    return text.c_str();
}

// Every control's value now, as the page's sets: "NAME=V;NAME=V1,V2,..."
// (ranges, checkboxes, colours, vectors; the first Program's value of a
// name). The page keeps it across a reload and gives each back through
// glimmer_view_set (a value a changed script no longer takes is dropped).
EMSCRIPTEN_KEEPALIVE const char* glimmer_view_sets() {
    static std::string text;
    text.clear();
    if (!liveViewer() || !liveViewer()->s.good || !liveViewer()->s.values) return text.c_str();
    std::set<std::string> seen;
    for (const auto& c : mergedUniforms(liveViewer()->s.good->plan)) {
        if (c.setting->form == UniformSetting::Form::Constant || !seen.insert(c.name).second) continue;
        std::string values;
        for (double x : liveViewer()->s.values->get(c.programs.front(), c.name)) values += (values.empty() ? "" : ",") + fmt::format("{}", x);
        if (!values.empty()) text += (text.empty() ? "" : ";") + c.name + "=" + values;
    }
    return text.c_str();
}

EMSCRIPTEN_KEEPALIVE int glimmer_view_errors() { return liveViewer() ? int(liveViewer()->s.errors.size()) : 0; }

}  // extern "C"
