// Geometry shaders written for NVIDIA's GL_EXT_geometry_shader4, made into
// standard GLSL before any GL (shader/gs4_translate.h does the text), and a
// missing input `layout` filled in from the primitive the Program draws.
#pragma once
#include "assets/assets.h"

namespace glimmer {

// Rewrites, in `assets.shaderTexts`, every loaded geometry shader that needs
// it. The input primitive of a shader without one is that of the first draw
// with its Program (a warning when later draws differ). One warning per
// shader file says what was done, at its first rewritten line. Line numbers
// stay the user's (the rewrite keeps every line where it was).
void adaptGeometryShaders(const Plan& plan, Assets& assets, Diagnostics& diags);

}  // namespace glimmer
