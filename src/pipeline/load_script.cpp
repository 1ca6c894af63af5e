#include "pipeline/load_script.h"

#include <fstream>
#include <iostream>
#include <ostream>

#include <fmt/format.h>

#include "pipeline/console.h"
#include "pipeline/error_cascades.h"
#include "pipeline/fold_diagnostics.h"
#include "lang/comment_notes.h"
#include "lang/parser.h"
#include "plan/limits.h"
#include "util/read_file.h"

namespace glimmer {

bool loadScript(const std::string& path, const PlanOptions& options, Diagnostics& diags, LoadedScript& out) {
    std::string text, why, name = path;
    if (path == "-") {
        // From standard input: the files it names resolve against the current
        // folder. Bounded like a file: at most kMaxScriptBytes.
        name = kStdinScriptName;
        std::vector<char> buf(4096);
        while (std::cin.read(buf.data(), std::streamsize(buf.size())) || std::cin.gcount() > 0) {
            text.append(buf.data(), size_t(std::cin.gcount()));
            if (text.size() > kMaxScriptBytes) {
                diags.error(name, {}, fmt::format("cannot read the script: it is larger than {} bytes", kMaxScriptBytes));
                return false;
            }
        }
    } else if (!readRegularFile(path, kMaxScriptBytes, text, why)) {
        diags.error(path, {}, why.rfind("cannot open", 0) == 0 ? "cannot open the script"
                                                               : "cannot read the script: it " + why);
        return false;
    }
    out.sources.add(name, text);
    out.script = parseScript(name, text, diags, options.maxMemoryBytes);
    out.plan = buildPlan(out.script, options, diags);
    for (auto& p : out.plan.programs)  // the script's own words about each pass, for the viewer
        if (std::string note = commentNoteAbove(text, p.loc.line); !note.empty())
            p.notes += (p.notes.empty() ? "" : "\n") + note;
    return true;
}

void printDiagnostics(const Diagnostics& diags, const SourceTexts& sources, std::ostream& out) {
    // Repeated glman-compatibility notes fold into one line (-v lists them,
    // -q keeps errors only); a script of a million bad lines must not flood
    // a grader's console.
    Verbosity v = verbosity();
    size_t notShown = 0;
    auto lines = foldDiagnostics(diags.all(), sources, v == Verbosity::Normal, v != Verbosity::Verbose,
                                 v != Verbosity::Quiet, kMaxPrintedDiagnostics, notShown);
    for (const auto& text : lines) out << text << (text.empty() || text.back() != '\n' ? "\n" : "");
    if (notShown > 0) out << fmt::format("... {} more diagnostics not shown\n", notShown);
    // Causes are counted, not the driver's lines: one undeclared sampler is
    // one error, not 51 (pipeline/error_cascades.h; the note above says how
    // many follow from it).
    const std::vector<int> causes = errorCauses(diags.all());
    int e = 0, w = 0;
    for (size_t i = 0; i < diags.all().size(); ++i) {
        if (causes[i] >= 0) continue;
        e += diags.all()[i].severity == Severity::Error;
        w += diags.all()[i].severity == Severity::Warning;
    }
    if (e > 0 && v == Verbosity::Quiet) out << fmt::format("{} error{}\n", e, e == 1 ? "" : "s");
    else if (e > 0) out << fmt::format("{} error{}, {} warning{}\n", e, e == 1 ? "" : "s", w, w == 1 ? "" : "s");
}

}  // namespace glimmer
