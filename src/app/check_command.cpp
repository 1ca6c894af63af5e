#include <iostream>

#include "process/session.h"
#include "pipeline/web_check.h"

namespace glimmer {

// Everything `render` would do before drawing, for every program and texture
// the script names, used or not.
int runCheck(const CheckOptions& o) {
    if (o.web) return runWebCheck(o);
    Session s;
    if (auto code = openSession(o, {}, true, s)) return *code;
    return kExitOk;
}

}  // namespace glimmer
