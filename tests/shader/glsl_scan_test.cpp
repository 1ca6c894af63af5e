// The GLSL scanning helpers (shader/glsl_scan.h): the #version directive,
// lines and the const leniency, on ordinary and hostile text.
#include "shader/glsl_scan.h"

#include <gtest/gtest.h>

namespace glimmer {
namespace {

TEST(GlslScan, ReadsTheVersionItsProfileAndLine) {
    GlslVersion v = glslVersionOf("// a shader\n  #  version 330 compatibility // why\nvoid main() {}\n");
    EXPECT_EQ(v.number, 330);
    EXPECT_EQ(v.profile, "compatibility");
    EXPECT_EQ(v.line, 2);
    EXPECT_TRUE(v.wellFormed);
}

TEST(GlslScan, NoDirectiveIsGlsl110OnLineZero) {
    GlslVersion v = glslVersionOf("void main() {}\n");
    EXPECT_EQ(v.number, 110);
    EXPECT_EQ(v.line, 0);
    EXPECT_EQ(v.profile, "");
}

TEST(GlslScan, ADirectiveInABlockCommentDoesNotCount) {
    GlslVersion v = glslVersionOf("/* old:\n#version 120\n*/\n#version 150\n");
    EXPECT_EQ(v.number, 150);
    EXPECT_EQ(v.line, 4);
    EXPECT_EQ(v.profile, "");
}

TEST(GlslScan, AHugeNumberSaturatesInsteadOfThrowing) {
    GlslVersion v = glslVersionOf("#version 99999999999999999999\n");
    EXPECT_EQ(v.number, kMaxGlslVersionNumber);
    EXPECT_EQ(v.line, 1);
}

TEST(GlslScan, JunkAfterTheProfileOrNoNumberIsNotWellFormed) {
    EXPECT_FALSE(glslVersionOf("#version 150 core junk\n").wellFormed);
    EXPECT_FALSE(glslVersionOf("#version core\n").wellFormed);
    EXPECT_TRUE(glslVersionOf("#version 150\r\n").wellFormed);
    // "#versionx" is another directive, not #version.
    EXPECT_EQ(glslVersionOf("#versionx 300\n").line, 0);
}

TEST(GlslScan, AThirtyThousandCharacterLineIsReadInOnePass) {
    GlslVersion v = glslVersionOf("#version 150 // " + std::string(30000, 'x') + "\n");
    EXPECT_EQ(v.number, 150);
    EXPECT_TRUE(v.wellFormed);
}

TEST(GlslScan, FindsTheFirstWholeWordWithAPrefix) {
    EXPECT_EQ(firstWordWithPrefix("'gl_Vertex' : undeclared identifier", "gl_"), "gl_Vertex");
    EXPECT_EQ(firstWordWithPrefix("my_gl_x and gl_Color", "gl_"), "gl_Color");  // not inside a word
    EXPECT_EQ(firstWordWithPrefix("gl_ alone", "gl_"), "");
    EXPECT_EQ(firstWordWithPrefix("nothing here", "gl_"), "");
    const std::string huge = "gl_" + std::string(200000, 'a');
    EXPECT_EQ(firstWordWithPrefix("`" + huge + "' undeclared", "gl_"), huge);
}

TEST(GlslScan, WordsAndLines) {
    const std::string text = "uniform vec3 uTint;\n\nvoid main() { x_1 = 2.5; }";
    EXPECT_EQ(lineStartOf(text, 1), 0u);
    EXPECT_EQ(lineStartOf(text, 3), 21u);
    EXPECT_EQ(lineStartOf(text, 4), std::string::npos);
    EXPECT_EQ(lineOf(text, 1), "uniform vec3 uTint;");
    EXPECT_EQ(lineOf(text, 2), "");
    EXPECT_EQ(lineOf(text, 3), "void main() { x_1 = 2.5; }");
    EXPECT_EQ(lineOf(text, 9), "");
}

TEST(GlslScan, WordCharacters) {
    EXPECT_TRUE(isGlslWordChar('_'));
    EXPECT_FALSE(isGlslWordChar('\xe9'));  // a byte of UTF-8 is never part of a GLSL identifier
    EXPECT_TRUE(isGlslWordStart('a'));
    EXPECT_FALSE(isGlslWordStart('7'));
}

// Read through the lexer: a directive after a block comment on its line
// counts, one continued over lines is one directive, comments after the
// profile are blanks.
TEST(GlslScan, TheVersionDirectiveAsTheLexerReadsIt) {
    // Number, profile, line and well-formedness in one line, for one EXPECT each.
    auto read = [](std::string_view text) {
        const GlslVersion v = glslVersionOf(text);
        return std::to_string(v.number) + " '" + v.profile + "' line " + std::to_string(v.line) +
               (v.wellFormed ? "" : " ill-formed");
    };
    EXPECT_EQ(read("/* a shader */ #version 330 /* the profile: */ core /* done */\n"), "330 'core' line 1");
    EXPECT_EQ(read("// #version 450\n#version \\\n 150 compatibility\n"), "150 'compatibility' line 2");
    EXPECT_EQ(glslVersionOf("// #version 450\n#version \\\n 150 compatibility\n").numberEnd, 31u);  // just past "150"
    EXPECT_EQ(glslVersionOf("void main() {}\n").numberEnd, std::string::npos);
    EXPECT_EQ(read("#version 150core\n"), "150 '' line 1 ill-formed");
    EXPECT_EQ(read("#version 1.5\n"), "1 '' line 1 ill-formed");
}

// NVIDIA's leniency: the last 'const' before the column on its line is
// blanked, not one in a comment or a longer word.
TEST(GlslScan, TheConstBeforeTheColumnIsBlanked) {
    const std::string text = "uniform float uK;\nconst float constant = uK; /* const */ const float k2 = uK;\n";
    EXPECT_EQ(withoutConstBefore(text, 2, 54),
              "uniform float uK;\nconst float constant = uK; /* const */       float k2 = uK;\n");
    EXPECT_EQ(withoutConstBefore(text, 2, 22), "uniform float uK;\n      float constant = uK; /* const */ const float k2 = uK;\n");
    EXPECT_EQ(withoutConstBefore(text, 1, 10), text);  // none before it on its line
    EXPECT_EQ(withoutConstBefore(text, 9, 1), text);   // no such line
}

}  // namespace
}  // namespace glimmer
