// Repeated warnings of one kind folded into one line. The seed bloom.glib
// alone warns five times that a uniform on a line of its own was taken as
// part of its Program; by default that is one line, and -v lists each.
#pragma once
#include <string>
#include <vector>

#include "lang/diagnostics.h"

namespace glimmer {

// What a warning is "of one kind" with: its message with every quoted name
// and every number taken out.
std::string diagnosticKind(const std::string& message);

// The text to print, one entry per diagnostic or folded group, in the order
// of the first of each. `fold`: warnings whose kind occurs twice or more
// become one summary line ("...; -v to list them"). `cascades`: errors that
// follow from an earlier one (pipeline/error_cascades.h) are counted in one
// line under it instead of printed. `warnings`: false drops every warning
// and note (-q). At most `maxLines` entries are formatted (a
// million diagnostics must not cost a million formatted source lines);
// `notShown` counts the entries left out.
std::vector<std::string> foldDiagnostics(const std::vector<Diagnostic>& all, const SourceTexts& sources, bool fold,
                                         bool cascades, bool warnings, size_t maxLines, size_t& notShown);

// The same entries with what each is: its severity (a folded group's is
// Warning) and its place to copy, "file:line" or the file alone. The
// viewer's panel lists these, so it counts what the terminal and the page
// count.
struct FoldedDiagnostic {
    Severity severity = Severity::Warning;
    std::string text;
    std::string where;
};
std::vector<FoldedDiagnostic> foldDiagnosticEntries(const std::vector<Diagnostic>& all, const SourceTexts& sources,
                                                    bool fold, bool cascades, bool warnings, size_t maxLines,
                                                    size_t& notShown);

}  // namespace glimmer
