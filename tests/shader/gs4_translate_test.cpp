// GL_EXT_geometry_shader4 -> GLSL 1.50 text rewriting: every rewrite, index
// expressions with brackets inside, swizzles, comments and strings left
// alone, and the line count kept so compiler lines stay the user's.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "shader/gs4_translate.h"

using namespace glimmer;

namespace {

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(Gs4Translate, PositionInBecomesGlInWithSwizzleKept) {
    auto r = translateGs4("vec3 V0 = gl_PositionIn[0].xyz;\n");
    EXPECT_EQ(r.text, "vec3 V0 = gl_in[0].gl_Position.xyz;\n");
    EXPECT_TRUE(r.usesExt);
    EXPECT_EQ(r.firstExtLine, 1);
}

TEST(Gs4Translate, IndexExpressionsWithBracketsAndCallsInside) {
    auto r = translateGs4("p = gl_PositionIn[ idx[i + 1] * f(a[2], b) ].xy + gl_PositionIn[(i+1)%3];\n");
    EXPECT_EQ(r.text, "p = gl_in[ idx[i + 1] * f(a[2], b) ].gl_Position.xy + gl_in[(i+1)%3].gl_Position;\n");
}

TEST(Gs4Translate, IndexSpreadOverLinesKeepsTheLines) {
    const std::string in = "p = gl_PositionIn[\n  i\n].w; q = 1;\n";
    auto r = translateGs4(in);
    EXPECT_EQ(r.text, "p = gl_in[\n  i\n].gl_Position.w; q = 1;\n");
}

TEST(Gs4Translate, TheOtherPerVertexArrays) {
    auto r = translateGs4("c = gl_FrontColorIn[i]; t = gl_TexCoordIn[i][0].st; s = gl_PointSizeIn[ j ];\n"
                          "b = gl_BackColorIn[1]; f = gl_FogFragCoordIn[2];\n");
    EXPECT_EQ(r.text, "c = gl_in[i].gl_FrontColor; t = gl_in[i].gl_TexCoord[0].st; s = gl_in[ j ].gl_PointSize;\n"
                      "b = gl_in[1].gl_BackColor; f = gl_in[2].gl_FogFragCoord;\n");
    EXPECT_EQ(r.rewrites.size(), 5u);
}

TEST(Gs4Translate, VerticesInInCodeAndInASize) {
    auto r = translateGs4("varying in vec3 vN[gl_VerticesIn];\n"
                          "void main() { for (int i = 0; i < gl_VerticesIn; i++) {} }\n");
    EXPECT_EQ(r.text, "in vec3 vN[];\n"
                      "void main() { for (int i = 0; i < gl_in.length(); i++) {} }\n");
    // A size inside a function is a local array's: the count, not unsized.
    r = translateGs4("void main() { vec3 c[gl_VerticesIn]; }\n");
    EXPECT_EQ(r.text, "void main() { vec3 c[gl_in.length()]; }\n");
}

TEST(Gs4Translate, VaryingInAndOut) {
    auto r = translateGs4("varying in  vec3 vNormal[];\nvarying out vec3 gNormal;\nflat varying out int gId;\n"
                          "varying vec2 gST;\n");
    EXPECT_EQ(r.text, "in  vec3 vNormal[];\nout vec3 gNormal;\nflat out int gId;\nout vec2 gST;\n");
}

// Global declarations after a function are global again once its body
// closes (issue 40's sampled mutant gs4_translate.cpp:94 kept counting the
// function's braces as open): a helper above main is how classroom geometry
// shaders are often written.
TEST(Gs4Translate, DeclarationsAfterAFunctionAreGlobal) {
    auto r = translateGs4("vec3 mid(vec3 a, vec3 b) { if (true) { return (a + b) * .5; } return a; }\n"
                          "varying vec2 gST;\nvarying in vec3 vN[gl_VerticesIn];\n"
                          "void main() { vec3 c[gl_VerticesIn]; }\n");
    EXPECT_EQ(r.text, "vec3 mid(vec3 a, vec3 b) { if (true) { return (a + b) * .5; } return a; }\n"
                      "out vec2 gST;\nin vec3 vN[];\n"
                      "void main() { vec3 c[gl_in.length()]; }\n");
}

TEST(Gs4Translate, VaryingBeforeANewlineKeepsTheNewline) {
    auto r = translateGs4("varying\nout vec3 g;\n");
    EXPECT_EQ(r.text, "\nout vec3 g;\n");
}

TEST(Gs4Translate, CommentsAndStringsAreLeftAlone) {
    const std::string in = "// gl_PositionIn[0] in a comment\n"
                           "/* gl_VerticesIn\n   varying in */ x = 1;\n"
                           "#error \"gl_PositionIn[1]\"\n";
    auto r = translateGs4(in);
    EXPECT_EQ(r.text, in);
    EXPECT_FALSE(r.usesExt);
    EXPECT_EQ(r.firstExtLine, 0);
}

TEST(Gs4Translate, IdentifiersThatOnlyContainTheNamesStay) {
    const std::string in = "vec4 my_gl_PositionIn[3]; float gl_VerticesInX; x = my_gl_PositionIn[0].x;\n";
    EXPECT_EQ(translateGs4(in).text, in);
}

TEST(Gs4Translate, ExtensionLineBecomesEmptyAndLinesAreKept) {
    const std::string in = "#version 330 compatibility\n"
                           "#extension GL_EXT_gpu_shader4: enable\n"
                           "#extension GL_EXT_geometry_shader4: enable\n"
                           "layout( triangles_adjacency ) in;\n"
                           "layout( line_strip, max_vertices=200 ) out;\n"
                           "void main() {\n"
                           "  vec3 V0 = gl_PositionIn[0].xyz;\n"
                           "  EmitVertex( ); EndPrimitive( );\n"
                           "}\n";
    auto r = translateGs4(in, {"triangles"});
    EXPECT_EQ(lines(r.text), lines(in));
    EXPECT_EQ(r.text, "#version 330 compatibility\n"
                      "#extension GL_EXT_gpu_shader4: enable\n"
                      "\n"
                      "layout( triangles_adjacency ) in;\n"
                      "layout( line_strip, max_vertices=200 ) out;\n"
                      "void main() {\n"
                      "  vec3 V0 = gl_in[0].gl_Position.xyz;\n"
                      "  EmitVertex( ); EndPrimitive( );\n"
                      "}\n");
    EXPECT_TRUE(r.hasInputLayout);
    EXPECT_FALSE(r.addedInputLayout);  // the shader's own layout wins over the draw's
    EXPECT_EQ(r.firstExtLine, 3);
}

TEST(Gs4Translate, MissingInputLayoutComesFromTheDrawOnTheFirstCodeLine) {
    const std::string in = "#version 330 compatibility\r\n"
                           "#extension GL_EXT_geometry_shader4 : enable\r\n"
                           "// comment\r\n"
                           "layout(triangle_strip, max_vertices = 3) out;\r\n"
                           "void main() { gl_Position = gl_PositionIn[gl_VerticesIn - 1]; EmitVertex(); }\r\n";
    auto r = translateGs4(in, {"lines_adjacency"});
    EXPECT_TRUE(r.addedInputLayout);
    EXPECT_EQ(lines(r.text), lines(in));
    EXPECT_EQ(r.text, "#version 330 compatibility\r\n"
                      "\r\n"
                      "// comment\r\n"
                      "layout(lines_adjacency) in; layout(triangle_strip, max_vertices = 3) out;\r\n"
                      "void main() { gl_Position = gl_in[gl_in.length() - 1].gl_Position; EmitVertex(); }\r\n");
}

TEST(Gs4Translate, WithoutADrawPrimitiveNoLayoutIsAdded) {
    auto r = translateGs4("void main() { gl_Position = gl_PositionIn[0]; }\n");
    EXPECT_FALSE(r.addedInputLayout);
    EXPECT_FALSE(r.hasInputLayout);
}

TEST(Gs4Translate, OldVersionIsRaisedTo150Compatibility) {
    auto r = translateGs4("#version 120\n#extension GL_EXT_geometry_shader4 : enable\nvoid main() {}\n");
    EXPECT_EQ(r.text, "#version 150 compatibility\n\nvoid main() {}\n");
    // 1.50 has geometry shaders: its #version stays as written.
    for (const char* v : {"#version 150", "#version 150 compatibility", "#version 330"}) {
        r = translateGs4(std::string(v) + "\n#extension GL_EXT_geometry_shader4 : enable\nvoid main() {}\n");
        EXPECT_EQ(r.text, std::string(v) + "\n\nvoid main() {}\n");
        EXPECT_EQ(r.rewrites, std::vector<std::string>{"#extension GL_EXT_geometry_shader4 dropped"});
    }
}

// Only a #version line with its number is a version: a #line (or #if) with
// a number is left as written, and a bare #version, which the driver will
// refuse, is no version and no crash.
TEST(Gs4Translate, OnlyAVersionLineWithANumberIsRaised) {
    auto r = translateGs4("#line 5\n#extension GL_EXT_geometry_shader4 : enable\nvoid main() {}\n");
    EXPECT_EQ(r.text, "#line 5\n\nvoid main() {}\n");
    EXPECT_EQ(r.rewrites, std::vector<std::string>{"#extension GL_EXT_geometry_shader4 dropped"});
    r = translateGs4("#version\n#extension GL_EXT_geometry_shader4 : enable\nvoid main() {}\n");
    EXPECT_EQ(r.text, "#version\n\nvoid main() {}\n");
}

TEST(Gs4Translate, AStandardShaderIsUntouched) {
    const std::string in = "#version 330 compatibility\nlayout(triangles) in;\nlayout(points, max_vertices=1) out;\n"
                           "void main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }\n";
    auto r = translateGs4(in, {"triangles"});
    EXPECT_EQ(r.text, in);
    EXPECT_FALSE(r.changed());
}

TEST(Gs4Translate, EachKindOfRewriteIsListedOnce) {
    auto r = translateGs4("a = gl_PositionIn[0]; b = gl_PositionIn[1]; c = gl_PositionIn[2];\n");
    EXPECT_EQ(r.rewrites, (std::vector<std::string>{"gl_PositionIn[i] -> gl_in[i].gl_Position"}));
}

}  // namespace
