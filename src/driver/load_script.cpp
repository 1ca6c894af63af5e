#include "driver/load_script.h"

#include <fstream>
#include <iostream>
#include <ostream>

#include <fmt/format.h>

#include "driver/console.h"
#include "driver/fold_diagnostics.h"
#include "lang/parser.h"

namespace glimmer {

bool loadScript(const std::string& path, const PlanOptions& options, Diagnostics& diags, LoadedScript& out) {
    std::string text, name = path;
    if (path == "-") {
        // From standard input: the files it names resolve against the current folder.
        name = kStdinScriptName;
        text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    } else {
        std::ifstream f(path, std::ios::binary);
        if (!f) {
            diags.error(path, {}, "cannot open the script");
            return false;
        }
        text.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    out.sources.add(name, text);
    out.script = parseScript(name, text, diags);
    out.plan = buildPlan(out.script, options, diags);
    return true;
}

void printDiagnostics(const Diagnostics& diags, const SourceTexts& sources, std::ostream& out) {
    Verbosity v = verbosity();
    for (const auto& text : foldDiagnostics(diags.all(), sources, v == Verbosity::Normal, v != Verbosity::Quiet))
        out << text << (text.empty() || text.back() != '\n' ? "\n" : "");
    int e = diags.errorCount(), w = diags.warningCount();
    if (e > 0 && v == Verbosity::Quiet) out << fmt::format("{} error{}\n", e, e == 1 ? "" : "s");
    else if (e > 0) out << fmt::format("{} error{}, {} warning{}\n", e, e == 1 ? "" : "s", w, w == 1 ? "" : "s");
}

}  // namespace glimmer
