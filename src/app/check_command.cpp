#include <iostream>

#include "driver/session.h"

namespace glimmer {

// Everything `render` would do before drawing, for every program and texture
// the script names, used or not.
int runCheck(const CommonOptions& o) {
    Session s;
    if (auto code = openSession(o, {}, true, s)) return *code;
    return kExitOk;
}

}  // namespace glimmer
