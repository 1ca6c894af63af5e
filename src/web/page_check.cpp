// The page's Check: `glimmer check --web` of a script without GL (read,
// parse, plan, read its files, translate every shader to GLSL ES 3.00; the
// diagnostics printed exactly as the desktop prints them), over files the
// page has put into Emscripten's in-memory file system: the same lang,
// plan and translator code as the desktop build, not a fork.
//
// Contract, for the page (src/web/page/glimmer-page.js):
//   glimmer_check(path)        -> 0 no errors, 1 errors, 2 the file cannot be read
//                                 (`glimmer check --web`'s exit codes)
//   glimmer_last_output()      -> the diagnostics of the last check, as the
//                                 desktop's `glimmer check` prints them to stderr
#include <emscripten/emscripten.h>

#include <sstream>
#include <string>

#include "pipeline/console.h"
#include "pipeline/load_script.h"
#include "pipeline/prepare_script.h"
#include "pipeline/web_check.h"
#include "web/page_state.h"

namespace {
std::string lastOutput;
}

namespace glimmer_web {
// web_render.cpp and web_view.cpp report through the same glimmer_last_output.
void setLastOutput(std::string text) { lastOutput = std::move(text); }
}  // namespace glimmer_web

extern "C" {

EMSCRIPTEN_KEEPALIVE int glimmer_check(const char* path) {
    glimmer::setVerbosity(glimmer::Verbosity::Normal);  // the CLI's default: glman notes folded
    glimmer::Diagnostics diags;
    glimmer::LoadedScript loaded;
    bool read = glimmer::loadScript(path ? path : "", glimmer::PlanOptions{}, diags, loaded);
    // Then, as `glimmer check --web`: every file read, every shader
    // translated for WebGL 2 (what the page will say when it draws).
    if (read && !diags.hasErrors()) {
        glimmer::loadFiles(loaded, true, diags);
        glimmer::checkProgramsForWeb(loaded, diags);
    }
    std::ostringstream out;
    glimmer::printDiagnostics(diags, loaded.sources, out);
    lastOutput = out.str();
    if (!read) return 2;
    return diags.errorCount() > 0 ? 1 : 0;
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_last_output() { return lastOutput.c_str(); }

}  // extern "C"
