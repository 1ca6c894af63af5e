// One mistake, one message. A driver's compile log goes on after its first
// error with errors that only follow from it: one undeclared sampler makes
// Mesa reject the `texture` call and then list every overload it tried (51
// errors for one typo). The first is the student's mistake; the rest are
// counted under it, and -v lists them all.
#pragma once
#include <vector>

#include "lang/diagnostics.h"

namespace glimmer {

// For each diagnostic of `all`, the index of the error it follows from, or
// -1 (a cause, or a diagnostic of its own). Only driver errors of one shader
// file, in one unbroken run, follow from the first of the run, when they are
// on a line the run already reported, repeat its first message (the same
// undeclared name used again), or name the type Mesa gives an expression
// that already failed (`error`, as in "texture(error, vec2)"). The driver's
// warnings about that file while the run lasts follow from it too.
std::vector<int> errorCauses(const std::vector<Diagnostic>& all);

}  // namespace glimmer
