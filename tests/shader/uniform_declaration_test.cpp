// Where a shader declares a uniform, for the unset-uniform warning (issue 19).
#include <gtest/gtest.h>

#include "shader/uniform_declaration.h"

namespace glimmer {
namespace {

TEST(UniformDeclaration, FindsTheLineOutsideComments) {
    const std::string text = "#version 330 compatibility\n"
                             "// uniform float uKd;  (a comment, not the declaration)\n"
                             "/* uniform float uKd;\n"
                             "   still a comment */\n"
                             "uniform float uKa, uKd;   // two on one line\n"
                             "uniform vec3 uKdColor;\n"
                             "uniform  mat4\n"
                             "    uM;\n";
    EXPECT_EQ(uniformDeclarationLine(text, "uKd"), 5);
    EXPECT_EQ(uniformDeclarationLine(text, "uKa"), 5);
    EXPECT_EQ(uniformDeclarationLine(text, "uKdColor"), 6);
    EXPECT_EQ(uniformDeclarationLine(text, "uM"), 0);  // split over lines: not found, no line is shown
    EXPECT_EQ(uniformDeclarationLine(text, "uNone"), 0);
    EXPECT_EQ(uniformDeclarationLine("float uKd = 1.; uniform float uX;", "uKd"), 0);  // not after 'uniform'
}

// Each 'uniform' on a line is its own declaration, up to its own ';'; one
// in a directive is found where it is written.
TEST(UniformDeclaration, EachUniformOfALineReadsToItsSemicolon) {
    EXPECT_EQ(uniformDeclarationLine("uniform float uA; uniform float uKd;\n", "uKd"), 1);
    EXPECT_EQ(uniformDeclarationLine("uniform float uA; float uKd;\n", "uKd"), 0);  // a global, not a uniform
    EXPECT_EQ(uniformDeclarationLine("// uKd\n#define DECLARE \\\n  uniform float uKd;\nDECLARE\n", "uKd"), 3);
}

}  // namespace
}  // namespace glimmer
