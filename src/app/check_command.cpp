#include <iostream>

#include "process/session.h"
#include "pipeline/web_check.h"
#include "plan/inputs.h"

namespace glimmer {

// Everything `render` would do before drawing, for every program and texture
// the script names, used or not.
int runCheck(const CheckOptions& o) {
    if (o.web) return runWebCheck(o, o.listInputs ? &std::cout : nullptr);
    Session s;
    if (auto code = openSession(o, {}, true, s)) return *code;
    if (o.listInputs)
        for (const PlanInput& in : inputsOf(s.loaded.plan)) std::cout << in.path << "\n";
    return kExitOk;
}

}  // namespace glimmer
