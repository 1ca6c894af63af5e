// The compatibility profile's built-ins that a shader for WebGL 2 (GLSL ES
// 3.00) cannot have, and the ordinary uniforms and attributes that stand in
// for them: the contract between the translation (desktop GLSL -> GLSL ES)
// and the renderer, which feeds these names (gl/builtin_feed.h). One row per
// built-in, as clox's rules[] has one per token.
//
// Why a table: the translator renames by it and the renderer looks the same
// names up after linking; a name in one place only would be a silent black
// picture. tests/shader/compat_builtins_test.cpp checks it is consistent.
//
// The renderer feeds a program by these names whenever it declares them, on
// the desktop too, so the browser's way of drawing is tested natively
// (tests/render/builtin_feed_test.cpp).
#pragma once
#include <array>
#include <string_view>

namespace glimmer {

enum class CompatFeed {
    ModelViewProjection,         // uniform mat4: P * MV
    ModelView,                   // uniform mat4
    Projection,                  // uniform mat4
    Normal,                      // uniform mat3: transpose(inverse(mat3(MV)))
    ModelViewInverse,            // uniform mat4
    ProjectionInverse,           // uniform mat4
    ModelViewProjectionInverse,  // uniform mat4
    PointSize,                   // uniform float: the script's PointSize (ES has no glPointSize)
    Vertex,                      // attribute vec4: the position (w = 1)
    NormalAttrib,                // attribute vec3
    Color,                       // attribute vec4: the current colour, one value for the draw
    MultiTexCoord0,              // attribute vec4: (s, t, 0, 1)
};

struct CompatBuiltin {
    CompatFeed feed;
    std::string_view builtin;    // the compatibility profile's name
    std::string_view name;       // what the translation calls it
    std::string_view glslType;   // its declaration's type
    bool attribute;              // an attribute (vertex shader input), else a uniform
    int location;                // attributes: the location bound before linking; -1 for uniforms
};

inline constexpr std::array<CompatBuiltin, 12> kCompatBuiltins{{
    {CompatFeed::ModelViewProjection, "gl_ModelViewProjectionMatrix", "glimmer_ModelViewProjectionMatrix", "mat4", false, -1},
    {CompatFeed::ModelView, "gl_ModelViewMatrix", "glimmer_ModelViewMatrix", "mat4", false, -1},
    {CompatFeed::Projection, "gl_ProjectionMatrix", "glimmer_ProjectionMatrix", "mat4", false, -1},
    {CompatFeed::Normal, "gl_NormalMatrix", "glimmer_NormalMatrix", "mat3", false, -1},
    {CompatFeed::ModelViewInverse, "gl_ModelViewMatrixInverse", "glimmer_ModelViewMatrixInverse", "mat4", false, -1},
    {CompatFeed::ProjectionInverse, "gl_ProjectionMatrixInverse", "glimmer_ProjectionMatrixInverse", "mat4", false, -1},
    {CompatFeed::ModelViewProjectionInverse, "gl_ModelViewProjectionMatrixInverse",
     "glimmer_ModelViewProjectionMatrixInverse", "mat4", false, -1},
    {CompatFeed::PointSize, "gl_Point.size", "glimmer_PointSize", "float", false, -1},
    // Locations 0 to 3 (the Tangent is at 7, gl/shader_build.h): a program
    // that declares none of these names is not affected by the binding.
    {CompatFeed::Vertex, "gl_Vertex", "glimmer_Vertex", "vec4", true, 0},
    {CompatFeed::NormalAttrib, "gl_Normal", "glimmer_Normal", "vec3", true, 1},
    {CompatFeed::Color, "gl_Color", "glimmer_Color", "vec4", true, 2},
    {CompatFeed::MultiTexCoord0, "gl_MultiTexCoord0", "glimmer_MultiTexCoord0", "vec4", true, 3},
}};

// The row of `feed`.
constexpr const CompatBuiltin& compatBuiltin(CompatFeed feed) { return kCompatBuiltins[size_t(feed)]; }

}  // namespace glimmer
