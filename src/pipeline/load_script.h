// The steps every front end shares before any GL: read a script, parse it,
// plan it; and print what was found along the way.
#pragma once
#include <iosfwd>
#include <string>

#include "assets/assets.h"
#include "lang/diagnostics.h"
#include "lang/script.h"
#include "plan/plan.h"

namespace glimmer {

struct LoadedScript {
    Script script;
    Plan plan;
    SourceTexts sources;  // the script's text, and shader texts once read
    Assets assets;        // the files it names, decoded (pipeline/prepare_script.h fills it)
};

// The name diagnostics give a script read from standard input ("-").
inline constexpr const char* kStdinScriptName = "<stdin>";

// Reads and parses `path` ("-": standard input) and builds its plan. False when the file cannot be
// read; the plan may still carry errors (check diags).
bool loadScript(const std::string& path, const PlanOptions& options, Diagnostics& diags, LoadedScript& out);

// Prints every diagnostic, clang style, then a summary line ("1 error,
// 6 warnings") when there were errors.
void printDiagnostics(const Diagnostics& diags, const SourceTexts& sources, std::ostream& out);

}  // namespace glimmer
