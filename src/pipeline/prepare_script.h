// The one sequence every front end runs to get a script ready to draw:
//
//   read + parse (lang) -> plan (plan) -> load files on the CPU (assets)
//     -> make a Renderer on the current context -> upload (gl)
//
// render, check, sheet, view, tradeoff and glimmer-bench all come through
// here, so a new step (a sandbox check, a memory budget) is added once.
// The CPU steps stop at the first step with errors; the GL steps still run
// when files are missing, so one run reports every shader error too.
#pragma once
#include <memory>
#include <string>

#include "pipeline/load_script.h"
#include "gl/proc_address.h"
#include "gl/renderer.h"

namespace glimmer {

struct ScriptRequest {
    std::string script;        // the .glib file
    PlanOptions plan;          // size, -I folders, targets to keep
    bool everything = false;   // `check`: every program and texture, not only what the picture needs
};

// Read, parse, plan (no GL). False, with diagnostics, when the script cannot
// be read or its plan has errors.
bool planScript(const ScriptRequest& request, Diagnostics& diags, LoadedScript& out);

// The CPU load step for a planned script (no GL). False when a file failed.
bool loadFiles(LoadedScript& script, bool everything, Diagnostics& diags);

// Uploads a planned and loaded script on an existing renderer (a front end
// that keeps one context and renderer for many scripts). The decoded files
// are released afterwards: the GL copies are what draws.
bool uploadScript(Renderer& renderer, LoadedScript& script, bool everything, Diagnostics& diags);

// loadFiles, then uploadScript (even when a file failed, so shader errors
// are reported in the same run). False on any error.
bool loadAndUpload(Renderer& renderer, LoadedScript& script, bool everything, Diagnostics& diags);

// All of it on the current context: planScript, loadFiles, a new Renderer
// through `getProc`, uploadScript. Null (with diagnostics) on any error.
std::unique_ptr<Renderer> prepareScript(const ScriptRequest& request, const GetProcAddress& getProc,
                                        Diagnostics& diags, LoadedScript& out);
// The same on an existing renderer. False on any error.
bool prepareScript(const ScriptRequest& request, Renderer& renderer, Diagnostics& diags, LoadedScript& out);

}  // namespace glimmer
