// Uniforms a Program's shaders read but its script line never sets. OpenGL
// starts every uniform at 0, so a lighting coefficient left out gives a black
// picture and a pattern's parameters left out a plain object, with no word
// why. Glimmer says which, where the shader declares it, and where in the
// script a value or slider for it would go.
#pragma once
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gl/uniform_upload.h"
#include "gl/unset_uniform.h"

namespace glimmer {

// The uniforms of `active` that `decl` does not set. Left out: samplers
// (they read unit 0 unless set, which the sampler-kind check covers),
// glman's built-ins (Timer, Noise2, Noise3), Glimmer's fed compatibility
// stand-ins (glimmer_*) and struct members.
// A uniform its shader gives a value of its own (`uniform float a = 1.;`,
// named in `initialized`) is not left at 0, so it is not listed either.
std::vector<UnsetUniform> unsetUniforms(const ProgramDecl& decl, const std::vector<ActiveUniform>& active,
                                        const std::set<std::string>& initialized = {});

// One warning per uniform of `active` that `decl` does not set, at the
// Program's line (those of unsetUniforms). `texts` are the stages' shader texts, in the order of decl.stages.
void warnUnsetUniforms(const ProgramDecl& decl, const std::vector<ActiveUniform>& active,
                       const std::set<std::string>& initialized,
                       const std::vector<std::optional<std::string>>& texts, const std::string& scriptFile,
                       Diagnostics& diags);

}  // namespace glimmer
