// Checks on a planned script that no single layer can make: a script that
// draws nothing renders only its clear colour, which is almost always a
// mistake worth a warning.
#pragma once
#include "lang/diagnostics.h"
#include "plan/plan.h"

namespace glimmer {

// True when some pass draws something (a quad, a shape, a glBegin list).
bool drawsSomething(const Plan& plan);

// A warning at the script when it draws nothing.
void warnIfDrawsNothing(const Plan& plan, Diagnostics& diags);

}  // namespace glimmer
