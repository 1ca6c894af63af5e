// Step one of the translation for WebGL 2 (shader/web_translate.h), as text:
// a desktop shader with the compatibility profile's built-ins becomes core
// GLSL that glslang can compile to SPIR-V. The built-ins become their
// stand-ins (shader/compat_builtins.h), declared once at the top; the
// renderer feeds those names (gl/builtin_feed.h).
//
// Contract:
//   - Output: `#version N core` (N = the shader's version, at least 330),
//     the stand-ins' declarations (only those the shader uses), then
//     `#line 1` and the user's text, its #version line left blank, so a
//     compiler's line numbers are the user's lines. Columns after a rename on
//     the same line move; `renames` lets a message find the user's spelling.
//   - Comments are left alone; identifiers are rewritten everywhere else,
//     #define bodies included (a macro that names gl_Vertex keeps working).
//   - Rewrites:
//       a built-in of the table      -> its stand-in (attributes in the vertex stage only)
//       gl_Point.size                -> glimmer_PointSize
//       ftransform()                 -> glimmer_ftransform() (P * MV * vertex, declared)
//       gl_FragColor / gl_FragData   -> glimmer_FragColor / glimmer_FragData[4] (fragment)
//       gl_FrontColor (vertex), gl_Color (fragment) -> the varying glimmer_FrontColor
//       gl_TexCoord[k], k a literal 0..7 -> the varying glimmer_TexCoordk
//       texture2D, texture3D, textureCube[Lod|Proj...] -> texture, textureLod, textureProj...
//       attribute                    -> in (vertex)
//       varying                      -> out (vertex), in (fragment)
//   - `aliases`: #define-style names that stand for built-ins (GSTAP's
//     aVertex for gl_Vertex, ...): rewritten as the built-in they name.
//   - Anything else of the compatibility profile (gl_LightSource, gl_BackColor,
//     gl_TexCoord[i] with i not a literal, ...) is left as written: the
//     compiler then reports it at its line.
#pragma once
#include "shader/glsl_scan.h"
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace glimmer {

enum class CompatStage { Vertex, Fragment };

struct CompatRewrite {
    std::string text;              // what glslang compiles
    int version = 110;             // the user's #version (110 when none)
    std::string profile;           // "", "core", "compatibility" or "es"
    int versionLine = 0;           // 1-based line of the user's #version (0: none)
    std::vector<std::string> declared;              // the stand-ins declared, in order
    std::map<std::string, std::string> renames;     // new name -> the user's spelling (first seen)
};

// `aliases`: name -> the built-in it stands for (from `#define A B` lines).
CompatRewrite rewriteCompatBuiltins(std::string_view source, CompatStage stage,
                                    const std::map<std::string, std::string>& aliases = {});

// The `#define A B` lines of a prelude (gl/shader_build.h's GSTAP) as A -> B.
std::map<std::string, std::string> definesOf(std::string_view prelude);

// The shader's #version line: glslVersionOf in shader/glsl_scan.h.

}  // namespace glimmer
