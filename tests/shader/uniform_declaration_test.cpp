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

}  // namespace
}  // namespace glimmer
