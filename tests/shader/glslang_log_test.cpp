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

// Each message line is one diagnostic at the user's line and column, a
// summary line dropped; a log whose last line has no newline (glslang ends each
// with one today) is read to its end once, not again from the start.
TEST(GlslangLog, EachMessageIsOneDiagnosticTheLastWithoutANewlineToo) {
    const std::string text = "uniform vec3 uKdColor, uKd;\nvoid main() { x = 1.; }\n";
    const GlslangLogContext cx{"s.frag", text, nullptr, ""};
    for (const std::string end : {"\n", ""}) {
        SCOPED_TRACE(end.empty() ? "no newline at the end" : "a newline at the end");
        Diagnostics diags;
        EXPECT_EQ(mapGlslangLog("WARNING: 0:1: 'uKd' : unused\nERROR: 1 compilation errors.  No code generated.\n"
                                "ERROR: 0:2: 'x' : undeclared identifier" + end,
                                cx, diags),
                  1);
        ASSERT_EQ(diags.all().size(), 2u);
        EXPECT_EQ(diags.all()[0].severity, Severity::Warning);
        EXPECT_EQ(diags.all()[0].loc.line, 1);
        EXPECT_EQ(diags.all()[0].loc.col, 24);
        EXPECT_EQ(diags.all()[1].severity, Severity::Error);
        EXPECT_EQ(diags.all()[1].loc.line, 2);
        EXPECT_EQ(diags.all()[1].loc.col, 15);
        EXPECT_EQ(diags.all()[1].message, "'x': undeclared identifier");  // tidied
    }
}

}  // namespace
}  // namespace glimmer
