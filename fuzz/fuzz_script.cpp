// libFuzzer: the script front end (lexer, parser, planner, diagnostics
// printing) on arbitrary text. No files are read: the plan runs with
// --sandbox in an empty folder, so every name resolves to nothing.
#include <cstddef>
#include <cstdint>
#include <string>

#include "lang/diagnostics.h"
#include "lang/parser.h"
#include "plan/plan.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glimmer;
    const std::string text(reinterpret_cast<const char*>(data), size);
    Diagnostics diags;
    Script script = parseScript("/nonexistent/fuzz.glib", text, diags);
    PlanOptions options;
    options.sandbox = true;
    Plan plan = buildPlan(script, options, diags);
    SourceTexts sources;
    sources.add("/nonexistent/fuzz.glib", text);
    std::size_t shown = 0;
    for (const auto& d : diags.all()) {
        if (shown++ == kMaxPrintedDiagnostics) break;
        if (formatDiagnostic(d, sources).empty()) __builtin_trap();
    }
    return 0;
}
