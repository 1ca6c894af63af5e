// The column of the token a glslang message names, on the user's line
// (shader/glslang_log.h): whole tokens of the lexer, as the compiler read them.
#include "shader/glslang_log.h"

#include <gtest/gtest.h>

namespace glimmer {
namespace {

TEST(GlslangLog, ATokensColumnIsWhereItStandsWhole) {
    const std::string text = "uniform vec3 uKdColor, uKd;\n  if (a <= b) c = d; // e = f\n#extension GL_foo : require\n";
    EXPECT_EQ(columnOf(text, 1, "uKd"), 24);        // not the start of uKdColor
    EXPECT_EQ(columnOf(text, 2, "="), 17);          // not inside "<="
    EXPECT_EQ(columnOf(text, 2, "e"), 0);           // only in the comment
    EXPECT_EQ(columnOf(text, 2, "c = d"), 15);      // a run of tokens, spaces and all
    EXPECT_EQ(columnOf(text, 3, "GL_foo"), 12);     // a directive's own words
    EXPECT_EQ(columnOf(text, 9, "uKd"), 0);         // no such line
    EXPECT_EQ(columnOf(text, 1, ""), 0);
}

}  // namespace
}  // namespace glimmer
