// A uniform a Program's shaders read and its script never sets, as the
// warning names it and the viewer's panel offers it (gl/unset_uniforms.h
// finds them). No GL here: the panel includes it through the renderer.
#pragma once
#include <string>

namespace glimmer {

struct UnsetUniform {
    std::string name;
    std::string type;     // its GLSL type: "float", "int", "bool", "vec3", ...
    int size = 1;         // array length
    std::string example;  // what would set it on the Program line, "uKa <0. 1. 1.>"; "" for none
    bool settable = true;  // some GLIB form on the Program line sets its type (none sets uint, uvec2-4, double)
};

}  // namespace glimmer
