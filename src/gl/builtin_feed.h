// Feeds a program the stand-ins for the compatibility built-ins
// (shader/compat_builtins.h): the matrices as uniforms, the vertex, normal,
// colour and texture coordinate as attributes. This is how every draw works
// in WebGL 2, which has no fixed-function state; on the desktop a program
// that declares these names is fed the same way, so the browser's path is
// tested by the native pixel tests.
#pragma once
#include <array>

#include <glm/glm.hpp>

#include "shader/compat_builtins.h"

namespace glimmer {

struct GlApi;

struct BuiltinFeed {
    // Per kCompatBuiltins row: the uniform or attribute location; -1 when
    // the program does not declare it.
    std::array<int, kCompatBuiltins.size()> location{};
    bool any = false;  // the program declares at least one: it is fed, not the fixed-function state
};

// Binds the attribute names to their locations: before linking.
void bindBuiltinAttributes(const GlApi& gl, unsigned program);
// What a linked program declares.
BuiltinFeed findBuiltinFeed(const GlApi& gl, unsigned program);

// The matrices and values of one draw, computed as OpenGL computes its
// built-ins from the matrix stacks.
struct BuiltinValues {
    glm::mat4 projection{1.f}, modelView{1.f};
    glm::vec4 color{1.f};
    float pointSize = 1.f;
};
// Uploads the uniforms into the program in use.
void feedBuiltinUniforms(const GlApi& gl, const BuiltinFeed& feed, const BuiltinValues& v);
// Points the attributes at the bound vertex buffer (MeshVertex layout) and
// sets the colour as a constant attribute; `disable` undoes the arrays.
void enableBuiltinAttributes(const GlApi& gl, const BuiltinFeed& feed, const BuiltinValues& v);
void disableBuiltinAttributes(const GlApi& gl, const BuiltinFeed& feed);

}  // namespace glimmer
