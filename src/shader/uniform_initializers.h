// `uniform float uY0 = 1.;`: GLSL 1.20 and later let a uniform start at a
// value of its own, and classroom shaders use it. GLSL ES 3.00 (WebGL 2)
// does not, so for the page the initialisers are taken out of the text and
// their values set by the renderer once the program links; the desktop keeps
// them, and a uniform with one is never "left at 0" (gl/unset_uniforms.h).
//
// Contract:
//   - The text that comes back has the same lines and columns: each
//     " = VALUE" is blanked, never removed.
//   - Values are read when they are numbers, true/false, or a constructor
//     of a float, int, bool or vector type with such arguments (`vec3(0.,
//     .5, 1.)`, `vec4(1.)`); anything else is listed in `unreadable`, with
//     its place, for an error that says so.
//   - Comments and the preprocessor's lines are skipped; one bounded pass.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace glimmer {

struct UniformInitializer {
    std::string name;
    std::string type;           // "float", "vec3", ...
    std::vector<float> values;  // one per component (a vecN(x) constructor: x repeated)
    int line = 0, col = 0;      // of the value, 1-based
};

struct UniformInitializers {
    std::string text;  // the shader with the initialisers blanked
    std::vector<UniformInitializer> values;
    std::vector<UniformInitializer> unreadable;  // name, type and place only
};

UniformInitializers takeUniformInitializers(std::string_view text);

}  // namespace glimmer
