#include <iostream>

#include "app/subcommands.h"
#include "process/session.h"
#include "pipeline/watch.h"
#include "pipeline/web_check.h"
#include "plan/inputs.h"

namespace glimmer {

// Everything `render` would do before drawing, for every program and texture
// the script names, used or not.
int runCheck(const CheckOptions& o) {
    if (o.web && !o.watch.empty()) {
        // A watch is checked by the driver that will draw it; the page checks its own as it starts one.
        std::cerr << "glimmer: error: --watch is checked on an OpenGL context: give it without --web\n";
        return kExitUsage;
    }
    if (o.web) return runWebCheck(o, o.listInputs ? &std::cout : nullptr);
    Session s;
    if (auto code = openSession(o, {}, true, s)) return *code;
    if (!o.watch.empty()) {
        Watch watch;
        if (auto code = startWatchOption(o.watch, s, watch)) return *code;
        std::cout << "watch " << watchTitle(watch, s.loaded.plan) << ": can be watched\n";
    }
    if (o.listInputs)
        for (const PlanInput& in : inputsOf(s.loaded.plan)) std::cout << in.path << "\n";
    return kExitOk;
}

}  // namespace glimmer
