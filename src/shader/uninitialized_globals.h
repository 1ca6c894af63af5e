// Telling the driver's false alarms from its true ones. Mesa warns "`gK' used
// uninitialized" inside a helper function that reads a global, even when
// main sets the global before it calls any function: it judges each
// function alone. Classroom shaders do this all the time (main computes a
// value into a global, then calls the lighting function), so the true
// warning ("`t' used uninitialized" for a local never set) drowns among the
// false ones. A text check (no compiler): it answers "false alarm" only when
// it can see it is one.
#pragma once
#include <string>

namespace glimmer {

// The line where `main` sets the global `name` before it calls any function
// the shader defines, when the driver's "used uninitialized" warning at
// `warningLine` is about a read inside another function (a false alarm);
// 0 when that cannot be shown (then the warning may be true and stays).
// `text` is the shader as the user wrote it (lines as the warning counts).
int globalSetByMainFirst(const std::string& text, const std::string& name, int warningLine);

}  // namespace glimmer
