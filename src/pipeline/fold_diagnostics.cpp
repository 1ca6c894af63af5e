#include "pipeline/fold_diagnostics.h"

#include "pipeline/error_cascades.h"

#include <cctype>
#include <map>

#include <fmt/format.h>

namespace glimmer {
namespace {

// Kinds with a summary of their own; any other repeated kind gets the
// generic one.
struct KnownKind {
    const char* contains;
    const char* summary;  // {} is the count
};

const KnownKind kKnown[] = {
    {"is on a line of its own; taken as part of Program",
     "{} uniforms on lines of their own were taken as part of their Program (glman needs a '\\'); -v to list them"},
    {"is not used by the shaders of Program", "{} uniforms are not used by the shaders of their Program; -v to list them"},
};

// "51 more errors and 1 warning follow from this one; -v shows them".
std::string followers(int errors, int warnings) {
    if (errors + warnings == 0) return {};
    auto count = [](int n, const char* what) { return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s"); };
    std::string what = errors > 0 ? count(errors, "more error") : std::string();
    if (warnings > 0) what += (what.empty() ? "" : " and ") + count(warnings, "warning");
    bool one = errors + warnings == 1;
    return fmt::format("{} follow{} from this one; -v shows {}", what, one ? "s" : "", one ? "it" : "them");
}

}  // namespace

std::string diagnosticKind(const std::string& message) {
    std::string out;
    for (size_t i = 0; i < message.size(); ++i) {
        char c = message[i];
        if (c == '\'') {
            size_t end = message.find('\'', i + 1);
            if (end != std::string::npos) {
                out += "'?'";
                i = end;
                continue;
            }
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i + 1 < message.size() &&
                   (std::isdigit(static_cast<unsigned char>(message[i + 1])) || message[i + 1] == '.'))
                ++i;
            out += '#';
            continue;
        }
        out += c;
    }
    return out;
}

std::vector<std::string> foldDiagnostics(const std::vector<Diagnostic>& all, const SourceTexts& sources, bool fold,
                                         bool cascades, bool warnings, size_t maxLines, size_t& notShown) {
    std::vector<std::string> out;
    for (FoldedDiagnostic& e : foldDiagnosticEntries(all, sources, fold, cascades, warnings, maxLines, notShown))
        out.push_back(std::move(e.text));
    return out;
}

std::vector<FoldedDiagnostic> foldDiagnosticEntries(const std::vector<Diagnostic>& all, const SourceTexts& sources,
                                                    bool fold, bool cascades, bool warnings, size_t maxLines,
                                                    size_t& notShown) {
    notShown = 0;
    std::vector<int> causes = cascades ? errorCauses(all) : std::vector<int>(all.size(), -1);
    // How many errors and warnings follow from each cause.
    std::vector<int> errorsAfter(all.size(), 0), warningsAfter(all.size(), 0);
    for (size_t i = 0; i < all.size(); ++i)
        if (causes[i] >= 0) ++(all[i].severity == Severity::Error ? errorsAfter : warningsAfter)[size_t(causes[i])];
    std::map<std::string, int> count;
    if (fold)
        for (const auto& d : all)
            if (d.severity == Severity::Warning) ++count[d.file + "\n" + diagnosticKind(d.message)];
    std::map<std::string, bool> printed;
    std::vector<FoldedDiagnostic> out;
    auto where = [](const Diagnostic& d) { return d.loc.line > 0 ? fmt::format("{}:{}", d.file, d.loc.line) : d.file; };
    for (size_t i = 0; i < all.size(); ++i) {
        const Diagnostic& d = all[i];
        if (d.severity != Severity::Error && !warnings) continue;
        if (causes[i] >= 0) continue;  // counted under its cause
        std::string key = d.file + "\n" + diagnosticKind(d.message);
        int n = d.severity == Severity::Warning && fold ? count[key] : 1;
        if (n >= 2) {
            if (printed[key]) continue;
            printed[key] = true;
        }
        if (out.size() == maxLines) {
            ++notShown;
            continue;
        }
        if (n < 2) {
            std::string text = formatDiagnostic(d, sources);
            if (std::string more = followers(errorsAfter[i], warningsAfter[i]); !more.empty())
                text += fmt::format("\n{}:{}: note: {}", sanitizeForTerminal(d.file, false), d.loc.line, more);
            out.push_back({d.severity, text, where(d)});
            continue;
        }
        std::string summary;
        for (const auto& k : kKnown)
            if (d.message.find(k.contains) != std::string::npos) summary = fmt::format(fmt::runtime(k.summary), n);
        if (summary.empty())
            summary = fmt::format("{} warnings like this one (line {} first): {}; -v to list them", n, d.loc.line,
                                  sanitizeForTerminal(d.message, false));
        // The message and the name come from the student's files: escaped,
        // as formatDiagnostic escapes a single one (issue 37: a script line
        // "ESC c" reset the teacher's terminal when it came twice).
        out.push_back({Severity::Warning, fmt::format("{}: warning: {}", sanitizeForTerminal(d.file, false), summary), d.file});
    }
    return out;
}

}  // namespace glimmer
