#include "pipeline/script_checks.h"

namespace glimmer {

bool drawsSomething(const Plan& plan) {
    for (const auto& pass : plan.passes)
        for (const auto& step : pass.steps)
            if (step.kind == Step::Kind::Draw) return true;
    return false;
}

void warnIfDrawsNothing(const Plan& plan, Diagnostics& diags) {
    if (!drawsSomething(plan))
        diags.warning(plan.scriptFile, {}, "the script draws nothing; the picture is only its background colour");
}

}  // namespace glimmer
