// Desktop GLSL -> GLSL ES 3.00 for WebGL 2 (shader/web_translate.h), on the
// CPU: a classroom shader pair with the compatibility built-ins comes out as
// ES 3.00 that keeps the names the renderer looks up; errors point at the
// user's own line and column; stages WebGL 2 lacks are refused. The output
// is also checked on a real OpenGL ES context in tests/render/web_translate_render_test.cpp.
#include <string>

#include <gtest/gtest.h>

#include "shader/compat_builtins.h"
#include "shader/glsl_scan.h"
#include "shader/web_translate.h"

using namespace glimmer;

namespace {

// No #version, attribute/varying, the built-ins, texture2D, an implicit
// int -> float conversion (`float x = 1;`), comments that name built-ins.
const char* kVertex = R"(// a classroom vertex shader: no #version, gl_Vertex in a comment stays
attribute vec3 Tangent;
varying vec2 vST;
varying vec3 vN;
uniform float uScale;
void main() {
    float x = 1;
    vST = gl_MultiTexCoord0.st * uScale * x;
    vN = normalize(gl_NormalMatrix * gl_Normal) + 0. * Tangent;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";
const char* kFragment = R"(varying vec2 vST;
varying vec3 vN;
uniform sampler2D uTex;
uniform float uAdd;
uniform int uCount;
void main() {
    float k = 2;
    vec4 c = texture2D(uTex, vST) * uCount;
    gl_FragColor = vec4(c.rgb * k + uAdd + vN, 1);
}
)";

struct Result {
    WebTranslation t;
    Diagnostics diags;
    std::string printed() const {
        std::string out;
        for (const Diagnostic& d : diags.all())
            out += d.file + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " + d.message + "\n";
        return out;
    }
};

Result translate(const std::string& text, WebStage stage, const std::string& prelude = "") {
    Result r;
    r.t = translateForWeb({text, stage, "user.glsl", prelude}, r.diags);
    return r;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// 1-based line and column of the first `token` in `text`.
std::pair<int, int> whereIs(const std::string& text, const std::string& token) {
    size_t at = text.find(token);
    EXPECT_NE(at, std::string::npos) << token;
    int line = 1;
    size_t lineStart = 0;
    for (size_t i = 0; i < at; ++i)
        if (text[i] == '\n') ++line, lineStart = i + 1;
    return {line, int(at - lineStart) + 1};
}

TEST(WebTranslate, AClassroomVertexShaderBecomesEs300WithTheStandIns) {
    Result r = translate(kVertex, WebStage::Vertex);
    ASSERT_TRUE(r.t.ok) << r.printed();
    const std::string& out = r.t.text;
    EXPECT_EQ(out.rfind("#version 300 es\n", 0), 0u) << out;
    for (CompatFeed f : {CompatFeed::ModelViewProjection, CompatFeed::Normal, CompatFeed::Vertex, CompatFeed::NormalAttrib,
                         CompatFeed::MultiTexCoord0}) {
        const CompatBuiltin& b = compatBuiltin(f);
        EXPECT_TRUE(has(out, std::string(b.name))) << b.name << " missing in\n" << out;
        EXPECT_FALSE(has(out, std::string(b.builtin))) << b.builtin << " left in\n" << out;
        if (b.attribute)  // the location the renderer binds, kept
            EXPECT_TRUE(has(out, "layout(location = " + std::to_string(b.location) + ") in " + std::string(b.glslType) +
                                     " " + std::string(b.name) + ";"))
                << out;
        else EXPECT_TRUE(has(out, "uniform " + std::string(b.glslType) + " " + std::string(b.name) + ";")) << out;
    }
    // Only what the shader uses is declared.
    EXPECT_FALSE(has(out, std::string(compatBuiltin(CompatFeed::Projection).name))) << out;
    EXPECT_TRUE(has(out, "uniform float uScale;")) << out;
    // The user's attribute keeps no location of the route's choosing: the
    // renderer binds it (Tangent) or the linker places it.
    EXPECT_TRUE(has(out, "\nin vec3 Tangent;")) << out;
    EXPECT_TRUE(has(out, "out vec2 vST;")) << out;
    EXPECT_TRUE(has(out, "out vec3 vN;")) << out;
    EXPECT_FALSE(has(out, "varying")) << out;
    EXPECT_FALSE(has(out, "attribute")) << out;
    EXPECT_TRUE(has(out, "= 1.0")) << "the int 1 became a float:\n" << out;
}

TEST(WebTranslate, AClassroomFragmentShaderBecomesEs300) {
    Result r = translate(kFragment, WebStage::Fragment);
    ASSERT_TRUE(r.t.ok) << r.printed();
    const std::string& out = r.t.text;
    EXPECT_EQ(out.rfind("#version 300 es\n", 0), 0u) << out;
    EXPECT_TRUE(has(out, "precision highp float;")) << out;
    EXPECT_TRUE(has(out, "sampler2D uTex;")) << out;
    EXPECT_TRUE(has(out, "uniform float uAdd;")) << out;
    EXPECT_TRUE(has(out, "uniform int uCount;")) << out;
    EXPECT_TRUE(has(out, "in vec2 vST;")) << out;  // matches the vertex stage's output by name
    EXPECT_TRUE(has(out, "in vec3 vN;")) << out;
    EXPECT_TRUE(has(out, "texture(uTex")) << out;
    EXPECT_FALSE(has(out, "texture2D")) << out;
    EXPECT_FALSE(has(out, "gl_FragColor")) << out;
    EXPECT_TRUE(has(out, "layout(location = 0) out vec4 ")) << out;
    EXPECT_FALSE(has(out, "binding")) << "ES 3.00 has no sampler bindings:\n" << out;
    EXPECT_EQ(r.diags.errorCount(), 0);
}

TEST(WebTranslate, EveryBuiltinOfTheTableTranslatesToItsStandIn) {
    for (const CompatBuiltin& b : kCompatBuiltins) {
        SCOPED_TRACE(std::string(b.builtin));
        std::string use = std::string(b.builtin);
        std::string type(b.glslType);
        std::string stmt = type == "mat4"   ? "gl_Position += " + use + " * vec4(1.);"
                           : type == "mat3" ? "gl_Position.xyz += " + use + " * vec3(1.);"
                           : type == "float" ? "gl_Position.x += " + use + ";"
                           : type == "vec3"  ? "gl_Position.xyz += " + use + ";"
                                             : "gl_Position += " + use + ";";
        Result r = translate("#version 120\nvoid main() {\n    gl_Position = vec4(0.);\n    " + stmt + "\n}\n",
                             WebStage::Vertex);
        ASSERT_TRUE(r.t.ok) << r.printed();
        EXPECT_TRUE(has(r.t.text, " " + type + " " + std::string(b.name) + ";")) << r.t.text;
    }
}

TEST(WebTranslate, FtransformAndGstapAliasesGoThroughTheStandIns) {
    Result r = translate("void main() { gl_Position = ftransform() + uModelViewMatrix * aVertex; }\n", WebStage::Vertex,
                         "#define uModelViewMatrix gl_ModelViewMatrix\n#define aVertex gl_Vertex\n");
    ASSERT_TRUE(r.t.ok) << r.printed();
    EXPECT_TRUE(has(r.t.text, std::string(compatBuiltin(CompatFeed::ModelViewProjection).name))) << r.t.text;
    EXPECT_TRUE(has(r.t.text, std::string(compatBuiltin(CompatFeed::ModelView).name))) << r.t.text;
    EXPECT_TRUE(has(r.t.text, std::string(compatBuiltin(CompatFeed::Vertex).name))) << r.t.text;
}

TEST(WebTranslate, ASyntaxErrorIsReportedAtTheUsersLineAndColumn) {
    // A #version line and a comment first: the header the translation puts
    // on top must not move the line.
    const std::string text = "#version 120\n// comment\nvoid main() {\n    float a = 1.0;\n    float b = a +* 2.0;\n"
                             "    gl_FragColor = vec4(b);\n}\n";
    Result r = translate(text, WebStage::Fragment);
    EXPECT_FALSE(r.t.ok);
    ASSERT_GE(r.diags.errorCount(), 1) << r.printed();
    const Diagnostic& d = r.diags.all().front();
    auto [line, col] = whereIs(text, "+*");
    EXPECT_EQ(d.file, "user.glsl");
    EXPECT_EQ(d.loc.line, line) << r.printed();
    EXPECT_EQ(d.loc.col, col + 1) << r.printed();  // on the '*' the parser did not expect
    EXPECT_TRUE(has(d.message, "syntax error")) << d.message;
}

TEST(WebTranslate, AnUndeclaredNameIsReportedWhereItStands) {
    const std::string text = "varying vec2 vST;\nvoid main() {\n    vec2 p = vST;\n    gl_FragColor = vec4(p, nothere, 1.);\n}\n";
    Result r = translate(text, WebStage::Fragment);
    EXPECT_FALSE(r.t.ok);
    ASSERT_GE(r.diags.errorCount(), 1) << r.printed();
    auto [line, col] = whereIs(text, "nothere");
    EXPECT_EQ(r.diags.all().front().loc.line, line) << r.printed();
    EXPECT_EQ(r.diags.all().front().loc.col, col) << r.printed();
    EXPECT_TRUE(has(r.diags.all().front().message, "'nothere'")) << r.printed();
}

// glman-era shaders pass the colour and texture coordinates through the
// fixed-function varyings: gl_FrontColor out, gl_Color in; gl_TexCoord[k].
TEST(WebTranslate, TheFixedFunctionVaryingsBecomeNamedVaryingsThatMatch) {
    Result v = translate("#version 330 compatibility\nvoid main() {\n    gl_FrontColor = gl_Color;\n"
                         "    gl_TexCoord[0] = gl_MultiTexCoord0;\n    gl_TexCoord[ 2 ] = vec4(1.);\n"
                         "    gl_Position = ftransform();\n}\n",
                         WebStage::Vertex);
    Result f = translate("#version 330 compatibility\nvoid main() {\n    gl_FragColor = gl_Color * gl_TexCoord[0].s;\n}\n",
                         WebStage::Fragment);
    ASSERT_TRUE(v.t.ok) << v.printed();
    ASSERT_TRUE(f.t.ok) << f.printed();
    EXPECT_TRUE(has(v.t.text, "out vec4 glimmer_FrontColor;")) << v.t.text;
    EXPECT_TRUE(has(v.t.text, "out vec4 glimmer_TexCoord0;")) << v.t.text;
    EXPECT_TRUE(has(v.t.text, "out vec4 glimmer_TexCoord2;")) << v.t.text;
    EXPECT_TRUE(has(v.t.text, "in vec4 glimmer_Color;")) << "the attribute stays the attribute:\n" << v.t.text;
    EXPECT_TRUE(has(f.t.text, "in vec4 glimmer_FrontColor;")) << f.t.text;
    EXPECT_TRUE(has(f.t.text, "in vec4 glimmer_TexCoord0;")) << f.t.text;
    EXPECT_FALSE(has(f.t.text, "glimmer_TexCoord2")) << "only what the stage uses:\n" << f.t.text;
}

// gl_MaxTextureCoords is 8: gl_TexCoord[0] to [7] become varyings, and
// gl_TexCoord[8] is the error it is on a desktop driver, at its own line.
TEST(WebTranslate, TexCoordPastTheLastIsAnError) {
    const std::string text = "#version 120\nvoid main() {\n    gl_TexCoord[7] = vec4(1.);\n    gl_TexCoord[8] = vec4(1.);\n"
                             "    gl_Position = vec4(0.);\n}\n";
    Result r = translate(text, WebStage::Vertex);
    EXPECT_FALSE(r.t.ok);
    ASSERT_GE(r.diags.errorCount(), 1) << r.printed();
    const Diagnostic& d = r.diags.all().front();
    EXPECT_EQ(d.loc.line, 4) << r.printed();
    EXPECT_EQ(d.loc.col, 5) << r.printed();
    EXPECT_EQ(d.message.rfind("'gl_TexCoord': undeclared identifier", 0), 0u) << r.printed();
}

// Each stage keeps its own words: 'attribute' in a fragment shader is an
// error there, as on the desktop, not an input.
TEST(WebTranslate, AttributeInAFragmentShaderIsAnError) {
    Result r = translate("#version 120\nattribute float a;\nvoid main() { gl_FragColor = vec4(a); }\n", WebStage::Fragment);
    EXPECT_FALSE(r.t.ok);
    ASSERT_GE(r.diags.errorCount(), 1) << r.printed();
    const Diagnostic& d = r.diags.all().front();
    EXPECT_EQ(d.loc.line, 2);
    EXPECT_EQ(d.loc.col, 1);
    EXPECT_EQ(d.message, "'attribute': not supported in this stage: fragment");
}

// gl_FragColor and gl_FragData in one shader: the desktop compiler refuses
// the pair, and so does the translation, at the user's line.
TEST(WebTranslate, FragColorAndFragDataTogetherAreAnErrorAtTheUsersLine) {
    Result r = translate("#version 120\nvoid main() {\n    gl_FragColor = vec4(1.);\n    gl_FragData[1] = vec4(0.);\n}\n",
                         WebStage::Fragment);
    EXPECT_FALSE(r.t.ok);
    ASSERT_GE(r.diags.errorCount(), 1) << r.printed();
    const Diagnostic& d = r.diags.all().front();
    EXPECT_EQ(d.loc.line, 4) << r.printed();
    EXPECT_EQ(d.loc.col, 5) << r.printed();
    EXPECT_NE(d.message.find("FragData'"), std::string::npos) << r.printed();
}

TEST(WebTranslate, ABuiltinWithNoStandInIsNamedAsSuch) {
    const std::string text = "void main() {\n    gl_FragColor = gl_LightSource[0].diffuse;\n}\n";
    Result r = translate(text, WebStage::Fragment);
    EXPECT_FALSE(r.t.ok);
    ASSERT_GE(r.diags.errorCount(), 1);
    const Diagnostic& d = r.diags.all().front();
    auto [line, col] = whereIs(text, "gl_LightSource");
    EXPECT_EQ(d.loc.line, line);
    EXPECT_EQ(d.loc.col, col);
    EXPECT_TRUE(has(d.message, "no stand-in")) << d.message;
}

TEST(WebTranslate, GeometryAndTessellationStagesAreRefused) {
    Result r = translate("#version 330 compatibility\nlayout(triangles) in;\nvoid main() {}\n", WebStage::Geometry);
    EXPECT_FALSE(r.t.ok);
    ASSERT_EQ(r.diags.errorCount(), 1);
    EXPECT_EQ(r.diags.all()[0].message,
              "WebGL 2 has no geometry shaders (GLSL ES 3.00 has only vertex and fragment shaders)");
    EXPECT_EQ(r.diags.all()[0].file, "user.glsl");
    for (WebStage s : {WebStage::TessControl, WebStage::TessEvaluation}) {
        Result t = translate("void main() {}\n", s);
        EXPECT_FALSE(t.t.ok);
        ASSERT_EQ(t.diags.errorCount(), 1);
        EXPECT_TRUE(has(t.diags.all()[0].message, "WebGL 2 has no tessellation")) << t.diags.all()[0].message;
    }
    EXPECT_TRUE(webRefusal(WebStage::Vertex).empty());
    EXPECT_TRUE(webRefusal(WebStage::Fragment).empty());
}

TEST(WebTranslate, AnEs300ShaderIsCheckedAndPassedOnAsItIs) {
    const std::string es = "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1.); }\n";
    Result r = translate(es, WebStage::Fragment);
    ASSERT_TRUE(r.t.ok) << r.printed();
    EXPECT_EQ(r.t.text, es);
    const std::string broken = "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = nothere; }\n";
    Result b = translate(broken, WebStage::Fragment);
    EXPECT_FALSE(b.t.ok);
    ASSERT_GE(b.diags.errorCount(), 1);
    EXPECT_EQ(b.diags.all().front().loc.line, 4) << b.printed();
}

TEST(WebTranslate, WhatEs300CannotSayIsAnErrorNotACrash) {
    // Doubles exist in desktop GLSL 4.00 and not in GLSL ES 3.00.
    Result r = translate("#version 400\nout vec4 c;\nuniform double uD;\nvoid main() { c = vec4(float(uD * 2.0lf)); }\n",
                         WebStage::Fragment);
    EXPECT_FALSE(r.t.ok);
    EXPECT_GE(r.diags.errorCount(), 1);
    EXPECT_TRUE(r.t.text.empty());
}

TEST(WebTranslate, GarbageIsAnErrorNotACrash) {
    for (std::string junk : {std::string(""), std::string("\0\x01\xff", 3), std::string("#version 9999\n"),
                             std::string("void main( {{{{"), std::string(5000, '('), std::string("#line 0 0\n#error x\n")}) {
        for (WebStage s : {WebStage::Vertex, WebStage::Fragment}) {
            Result r = translate(junk, s);
            EXPECT_FALSE(r.t.ok);
            EXPECT_GE(r.diags.errorCount(), 1);
        }
    }
}

// Issue 37: a global const set from a uniform loses its 'const', and the
// warning names it: the word before the column glslang points at, blanks
// between, never a number or a word cut short.
TEST(WebTranslate, AGlobalConstFromAUniformIsDroppedAndNamedInTheWarning) {
    const std::string head = "#version 330 compatibility\nuniform float uK;\n";
    Result r = translate(head + "const float k2 \t = uK * 2.;\nvoid main() { gl_FragColor = vec4(k2); }\n", WebStage::Fragment);
    ASSERT_TRUE(r.t.ok) << r.printed();
    EXPECT_EQ(r.printed(), "user.glsl:3:18: " + globalConstDropped("`k2'") + "\n");
    r = translate(head + "const vec4 k_3=vec4(uK);\nvoid main() { gl_FragColor = k_3; }\n", WebStage::Fragment);
    ASSERT_TRUE(r.t.ok) << r.printed();
    EXPECT_EQ(r.printed(), "user.glsl:3:15: " + globalConstDropped("`k_3'") + "\n");
}

TEST(WebTranslate, IsGlslEs300ReadsTheVersionLine) {
    EXPECT_TRUE(isGlslEs300("#version 300 es\nvoid main(){}"));
    EXPECT_TRUE(isGlslEs300("// hi\n  #  version 300 es\n"));
    EXPECT_FALSE(isGlslEs300("#version 330 core\n"));
    EXPECT_FALSE(isGlslEs300("void main(){}\n"));
    EXPECT_FALSE(isGlslEs300("/*\n#version 300 es\n*/\n"));
}

}  // namespace
