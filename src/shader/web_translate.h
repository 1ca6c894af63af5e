// Desktop GLSL (the compatibility profile classroom shaders are written in,
// with or without #version) -> GLSL ES 3.00, the only language WebGL 2
// accepts. No OpenGL: real compilers, on the CPU.
//
//   1. shader/compat_rewrite.h: the compatibility built-ins become the
//      stand-ins of shader/compat_builtins.h (the names the renderer feeds),
//      gl_FragColor an output, texture2D texture, attribute/varying in/out;
//      `#version N core` and `#line 1` on top.
//   2. glslang compiles that to SPIR-V for OpenGL, locations and bindings
//      mapped automatically (glslangValidator -G --aml --amb), errors
//      relaxed where glslang allows (EShMsgRelaxedErrors).
//   3. SPIRV-Cross writes GLSL ES 3.00 from the SPIR-V: uniforms, samplers
//      and attributes keep their names (the renderer finds them by name),
//      precision highp; the stand-in attributes keep the table's locations,
//      every other location and binding is left to the linker, since ES 3.00
//      has no layout for them.
//   4. glslang compiles the result as GLSL ES 3.00, so what is handed on is
//      known to be valid there.
//
// Errors are diagnostics against the user's file, line and column (the
// column of the token the compiler names, found on the user's line).
// Geometry and tessellation stages are refused: WebGL 2 has none.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostics.h"
#include "shader/uniform_initializers.h"

namespace glimmer {

enum class WebStage { Vertex, Fragment, Geometry, TessControl, TessEvaluation };

struct WebTranslateInput {
    std::string_view text;   // the shader as the user wrote it
    WebStage stage = WebStage::Vertex;
    std::string file;        // for diagnostics: the user's file
    // `#define A B` lines the shader is compiled after (GSTAP's aliases:
    // aVertex for gl_Vertex, ...), so the aliases are translated too.
    std::string_view prelude;
};

struct WebTranslation {
    bool ok = false;
    std::string text;  // GLSL ES 3.00 when ok
    // `uniform float uY0 = 1.;` has no GLSL ES 3.00 form: the initialisers,
    // taken out of the text, for the renderer to set once the program links
    // (shader/uniform_initializers.h).
    std::vector<UniformInitializer> initialValues;
};

// Translates one stage; every problem is added to `diags` (nothing throws).
WebTranslation translateForWeb(const WebTranslateInput& in, Diagnostics& diags);

// True when `text` already declares `#version 300 es` (nothing to translate).
bool isGlslEs300(std::string_view text);

// The reason a stage cannot run in WebGL 2, or empty when it can.
std::string webRefusal(WebStage stage);

// The stage's name as the script's command spells it ("geometry shader").
const char* webStageName(WebStage stage);

}  // namespace glimmer
