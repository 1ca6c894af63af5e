#include "driver/load_script.h"

#include <fstream>
#include <ostream>

#include <fmt/format.h>

#include "lang/parser.h"
#include "plan/limits.h"
#include "util/read_file.h"

namespace glimmer {

bool loadScript(const std::string& path, const PlanOptions& options, Diagnostics& diags, LoadedScript& out) {
    std::string text, why;
    if (!readRegularFile(path, kMaxScriptBytes, text, why)) {
        diags.error(path, {}, why.rfind("cannot open", 0) == 0 ? "cannot open the script"
                                                               : "cannot read the script: it " + why);
        return false;
    }
    out.sources.add(path, text);
    out.script = parseScript(path, text, diags);
    out.plan = buildPlan(out.script, options, diags);
    return true;
}

void printDiagnostics(const Diagnostics& diags, const SourceTexts& sources, std::ostream& out) {
    // A script of a million bad lines must not flood a grader's console.
    size_t printed = 0;
    for (const auto& d : diags.all()) {
        if (printed == kMaxPrintedDiagnostics) break;
        ++printed;
        std::string text = formatDiagnostic(d, sources);
        out << text << (text.empty() || text.back() != '\n' ? "\n" : "");
    }
    if (diags.all().size() > printed)
        out << fmt::format("... {} more diagnostics not shown\n", diags.all().size() - printed);
    int e = diags.errorCount(), w = diags.warningCount();
    if (e > 0)
        out << fmt::format("{} error{}, {} warning{}\n", e, e == 1 ? "" : "s", w, w == 1 ? "" : "s");
}

}  // namespace glimmer
