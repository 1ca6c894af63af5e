#include "pipeline/error_cascades.h"

#include <set>
#include <string>

namespace glimmer {
namespace {

// Mesa types an expression that already failed to compile as `error`, and
// names that type in every message it then causes: "no matching function for
// call to `texture(error, vec2)'", "... of type error ...".
bool namesFailedType(const std::string& m) {
    for (const char* mark : {"(error", ", error", "`error'", "type error", " error)"})
        if (m.find(mark) != std::string::npos) return true;
    return false;
}

}  // namespace

std::vector<int> errorCauses(const std::vector<Diagnostic>& all) {
    std::vector<int> cause(all.size(), -1);
    int first = -1;           // the error the current run started with
    std::set<int> runLines;   // the lines the run has reported
    for (size_t i = 0; i < all.size(); ++i) {
        const Diagnostic& d = all[i];
        if (d.severity != Severity::Error) {
            // A driver warning after an error of its file, in the same log:
            // the compile already failed, and what it warns about next (a
            // variable whose initialiser failed "used uninitialized") is most
            // often that failure again. Other warnings never break a run.
            if (first >= 0 && d.fromDriver && d.file == all[size_t(first)].file) cause[i] = first;
            continue;
        }
        if (first >= 0 && d.fromDriver && d.file == all[size_t(first)].file &&
            (runLines.count(d.loc.line) || d.message == all[size_t(first)].message || namesFailedType(d.message))) {
            cause[i] = first;
            runLines.insert(d.loc.line);
            continue;
        }
        first = d.fromDriver ? int(i) : -1;
        runLines = {d.loc.line};
    }
    return cause;
}

}  // namespace glimmer
