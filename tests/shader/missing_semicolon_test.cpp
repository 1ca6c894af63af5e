// A statement without its ';' marked at its own line's end, not on the next
// statement's line where every compiler reports it (issue 39; clang's way).
#include <gtest/gtest.h>

#include "shader/missing_semicolon.h"

namespace glimmer {
namespace {

constexpr const char* kShader =
    "#version 330 compatibility\n"        // 1
    "uniform float uAdd;\n"               // 2
    "void main( )\n"                      // 3
    "{\n"                                 // 4
    "    vec3 rgb = vec3(1.)  // white\n"  // 5: no ';', a comment after
    "\n"                                  // 6
    "    // the glow\n"                   // 7
    "    gl_FragColor = vec4(rgb, 1.);\n"  // 8
    "}\n";

TEST(MissingSemicolon, MesasAndGlslangsWordsPointAtTheEndOfTheStatementsOwnLine) {
    for (const char* said : {"syntax error, unexpected NEW_IDENTIFIER, expecting ',' or ';'",
                             "'gl_FragColor' : syntax error, unexpected IDENTIFIER, expecting COMMA or SEMICOLON"}) {
        auto at = missingSemicolonAt(said, kShader, 8);
        ASSERT_TRUE(at) << said;
        EXPECT_EQ(at->line, 5);
        EXPECT_EQ(at->col, 24);  // just past "vec3(1.)", before the comment
    }
}

TEST(MissingSemicolon, OtherMessagesAndLinesThatEndAStatementKeepTheDriversPlace) {
    EXPECT_FALSE(missingSemicolonAt("syntax error, unexpected NEW_IDENTIFIER", kShader, 8));
    EXPECT_FALSE(missingSemicolonAt("'x' : undeclared identifier", kShader, 8));
    // The line before ends with '{' (line 4), ';' or is a preprocessor line.
    EXPECT_FALSE(missingSemicolonAt("expecting ',' or ';'", kShader, 5));
    EXPECT_FALSE(missingSemicolonAt("expecting ',' or ';'", kShader, 9));
    EXPECT_FALSE(missingSemicolonAt("expecting ',' or ';'", kShader, 2));
    EXPECT_FALSE(missingSemicolonAt("expecting ',' or ';'", kShader, 1));
    EXPECT_FALSE(missingSemicolonAt("expecting ',' or ';'", "", 3));
}

}  // namespace
}  // namespace glimmer
