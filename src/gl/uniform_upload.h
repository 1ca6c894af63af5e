// Giving a Program's uniforms their values. The type comes from the shader's
// declaration, not from how the script wrote the number: `<0 3 3>` may feed
// a float and `<1. 28 128.>` an int.
#pragma once
#include <string>
#include <vector>

#include "gl/gl_api.h"
#include "lang/diagnostics.h"
#include "plan/plan.h"

namespace glimmer {

struct ActiveUniform {
    std::string name;  // without a trailing "[0]"
    GLenum type = 0;
    GLint size = 1;    // array length
    GLint location = -1;
};

std::vector<ActiveUniform> activeUniforms(const GlApi& gl, unsigned program);

// Warns about settings the shaders do not use and forms that do not fit the
// declared type; nothing here stops the script.
void checkUniformSettings(const ProgramDecl& decl, const std::vector<ActiveUniform>& active,
                          const std::string& scriptFile, Diagnostics& diags);

// Converts `values` to the uniform's declared type and uploads it to the
// program in use. Missing components are 0 (alpha 1 for a colour is filled
// in by the plan).
void uploadUniform(const GlApi& gl, const ActiveUniform& u, const std::vector<double>& values);

// The values a setting written in `form` gives a uniform of u's type, as
// glman converted them (checkUniformSettings warns about each case):
//   * one value (a range, a checkbox, a number, a one-item array) on a
//     vector or array: copied to every component; on a matrix: that many
//     times the identity (GLSL's mat3(x));
//   * a colour on a scalar: its luminance 0.2126 r + 0.7152 g + 0.0722 b;
//     on a vec2: r g; on a vec3: r g b; on a vec4: r g b a;
//   * anything else: component by component, missing ones 0, extra ones dropped.
// Ints round, bools are "not 0"; uploadUniform does that part.
std::vector<double> convertUniform(UniformSetting::Form form, const ActiveUniform& u, const std::vector<double>& values);

bool isSamplerType(GLenum type);

// Whether a value on a Program line (a range, an array, a colour, a bool)
// can set a uniform of this type: floats, ints, bools, their vectors and
// float matrices. Not unsigned ints, doubles and the rest (checkUniformSettings
// warns "it is not set"); not samplers, which a unit number sets.
bool glibFormSets(GLenum type);

// A uniform's type as GLSL spells it ("float", "vec3", "mat4", "uvec2");
// "sampler" for any sampler, "another type" for the rest.
std::string uniformTypeName(GLenum type);

// A sampler type as GLSL spells it ("sampler2D", "isampler3D",
// "samplerCubeShadow"); null for a type that is not a sampler.
const char* samplerTypeName(GLenum type);
// The kind of texture a sampler type reads: 2-D, 3-D or cube map (each with
// its int, unsigned and shadow forms); false for the kinds Glimmer never
// makes (1-D, arrays, rectangles, buffers, multisample) and non-samplers.
bool samplerTextureKind(GLenum type, TextureDecl::Kind& out);

}  // namespace glimmer
