// GL_EXT_geometry_shader4 -> standard GLSL, as text. NVIDIA's drivers accept
// the EXT forms (gl_PositionIn[], gl_VerticesIn, varying in/out) next to
// `#version 330 compatibility`; Mesa does not. This rewrites them into what
// GLSL 1.50 compatibility says, without OpenGL, so it can be tested alone.
//
// Contract:
//   - The output has exactly the input's lines: line N of the output is line
//     N of the input, rewritten in place, so a compiler's line numbers are
//     the user's. (Columns after an edit on the same line move.)
//   - Comments, strings and preprocessor lines other than
//     `#extension GL_EXT_geometry_shader4` and `#version` are left alone.
//   - Rewrites (index expressions may hold brackets, calls and newlines):
//       gl_PositionIn[e]        -> gl_in[e].gl_Position      (any swizzle after it stays)
//       gl_PointSizeIn[e]       -> gl_in[e].gl_PointSize
//       gl_FrontColorIn[e]      -> gl_in[e].gl_FrontColor    (and Back, FrontSecondary, BackSecondary)
//       gl_TexCoordIn[e][k]     -> gl_in[e].gl_TexCoord[k]
//       gl_FogFragCoordIn[e], gl_ClipVertexIn[e] likewise
//       gl_VerticesIn           -> gl_in.length()            ([] in a declaration's size at file scope)
//       varying in / varying out / varying (file scope) -> in / out / out
//       #extension GL_EXT_geometry_shader4 : ...      -> an empty line
//       #version below 150      -> #version 150 compatibility
//   - A shader with no input `layout(<primitive>) in;` gets one with
//     `inputPrimitive` (when given), put before its first declaration on
//     the same line.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace glimmer {

struct Gs4Options {
    // The input primitive of the draw, as a layout word: points, lines,
    // lines_adjacency, triangles, triangles_adjacency. Empty: not known.
    std::string inputPrimitive;
};

struct Gs4Result {
    std::string text;                // the rewritten shader, same line count
    bool usesExt = false;            // any EXT_geometry_shader4 form was found
    bool hasInputLayout = false;     // the shader declares its input primitive
    bool addedInputLayout = false;   // one was put in from Gs4Options::inputPrimitive
    int firstExtLine = 0;            // 1-based line of the first EXT form (0: none)
    std::vector<std::string> rewrites;  // each kind of rewrite done, once, e.g. "gl_VerticesIn -> gl_in.length()"
    bool changed() const { return usesExt || addedInputLayout; }
};

Gs4Result translateGs4(std::string_view source, const Gs4Options& options = {});

}  // namespace glimmer
