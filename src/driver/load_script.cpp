#include "driver/load_script.h"

#include <fstream>
#include <ostream>

#include <fmt/format.h>

#include "lang/parser.h"

namespace glimmer {

bool loadScript(const std::string& path, const PlanOptions& options, Diagnostics& diags, LoadedScript& out) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        diags.error(path, {}, "cannot open the script");
        return false;
    }
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    out.sources.add(path, text);
    out.script = parseScript(path, text, diags);
    out.plan = buildPlan(out.script, options, diags);
    return true;
}

void printDiagnostics(const Diagnostics& diags, const SourceTexts& sources, std::ostream& out) {
    for (const auto& d : diags.all()) {
        std::string text = formatDiagnostic(d, sources);
        out << text << (text.empty() || text.back() != '\n' ? "\n" : "");
    }
    int e = diags.errorCount(), w = diags.warningCount();
    if (e > 0)
        out << fmt::format("{} error{}, {} warning{}\n", e, e == 1 ? "" : "s", w, w == 1 ? "" : "s");
}

}  // namespace glimmer
