#include "lang/diagnostics.h"

#include <gtest/gtest.h>

namespace glimmer {
namespace {

TEST(Diagnostics, FormatsFileLineColumnSourceLineAndCaret) {
    SourceTexts src;
    src.add("a.glib", "##OpenGL GLIB\nFoo 1 2\n");
    Diagnostic d{Severity::Warning, "a.glib", {2, 5}, "something odd"};
    EXPECT_EQ(formatDiagnostic(d, src),
              "a.glib:2:5: warning: something odd\n"
              "Foo 1 2\n"
              "    ^");
}

TEST(Diagnostics, CaretLineCopiesTabsOfThePrefix) {
    SourceTexts src;
    src.add("a.glib", "\tProgram\t P  <0\n");
    Diagnostic d{Severity::Error, "a.glib", {1, 14}, "bad"};
    EXPECT_EQ(formatDiagnostic(d, src),
              "a.glib:1:14: error: bad\n"
              "\tProgram\t P  <0\n"
              "\t       \t    ^");
}

TEST(Diagnostics, CaretAtColumnOne) {
    SourceTexts src;
    src.add("f", "Zap");
    EXPECT_EQ(formatDiagnostic({Severity::Note, "f", {1, 1}, "here"}, src), "f:1:1: note: here\nZap\n^");
}

// The OpenGL driver's own words are marked as the driver's (issue 19).
TEST(Diagnostics, TheDriversMessagesSaySo) {
    SourceTexts src;
    src.add("g.frag", "    x += t;");
    EXPECT_EQ(formatDiagnostic({Severity::Warning, "g.frag", {1, 10}, "`t' used uninitialized", true}, src),
              "g.frag:1:10: warning: `t' used uninitialized [driver]\n    x += t;\n         ^");
}

TEST(Diagnostics, CaretPastTheEndOfTheLineIsPaddedWithSpaces) {
    SourceTexts src;
    src.add("f", "ab\n");
    EXPECT_EQ(formatDiagnostic({Severity::Error, "f", {1, 5}, "m"}, src), "f:1:5: error: m\nab\n    ^");
}

TEST(Diagnostics, CaretCountsAMultiByteCharacterOnce) {
    SourceTexts src;
    src.add("f", "Texture2D 5 caf\xC3\xA9 x\n");  // "café": é is two bytes
    // col 19 is the byte column of "x"; on screen it is the 18th character.
    EXPECT_EQ(formatDiagnostic({Severity::Error, "f", {1, 19}, "m"}, src),
              "f:1:19: error: m\nTexture2D 5 caf\xC3\xA9 x\n                 ^");
}

// A C1 control character (U+009B, CSI, two bytes in UTF-8) is a terminal
// escape as ESC is: escaped in the message and in the echoed line, and the
// caret still lands on the character after it (issue 30).
TEST(Diagnostics, C1ControlCharactersAreEscapedLikeC0Ones) {
    SourceTexts src;
    src.add("f", "Texture2D 5 a\xc2\x9b" "2J x\n");
    EXPECT_EQ(formatDiagnostic({Severity::Error, "f", {1, 19}, "m \xc2\x9b" "31m"}, src),
              "f:1:19: error: m \\xc2\\x9b31m\nTexture2D 5 a\\xc2\\x9b2J x\n                        ^");
    // U+00A0 and other characters from U+00A0 on are text, not controls.
    EXPECT_EQ(sanitizeForTerminal("caf\xc3\xa9 \xc2\xa0", false), "caf\xc3\xa9 \xc2\xa0");
}

TEST(Diagnostics, LineZeroGivesFileAndMessageOnly) {
    SourceTexts src;
    src.add("a.glib", "Foo\n");
    EXPECT_EQ(formatDiagnostic({Severity::Error, "a.glib", {0, 0}, "cannot open file"}, src),
              "a.glib: error: cannot open file");
}

TEST(Diagnostics, NoFileNameGivesSeverityAndMessage) {
    EXPECT_EQ(formatDiagnostic({Severity::Warning, "", {0, 0}, "no script given"}, SourceTexts{}),
              "warning: no script given");
}

TEST(Diagnostics, UnknownSourceOmitsSourceAndCaretLines) {
    EXPECT_EQ(formatDiagnostic({Severity::Error, "x.frag", {12, 3}, "syntax error"}, SourceTexts{}),
              "x.frag:12:3: error: syntax error");
}

TEST(Diagnostics, LineWithoutColumnShowsSourceButNoCaret) {
    SourceTexts src;
    src.add("x.frag", "a\nb = 1;\n");
    EXPECT_EQ(formatDiagnostic({Severity::Error, "x.frag", {2, 0}, "syntax error"}, src),
              "x.frag:2: error: syntax error\nb = 1;");
}

TEST(Diagnostics, SeverityNames) {
    EXPECT_STREQ(severityName(Severity::Note), "note");
    EXPECT_STREQ(severityName(Severity::Warning), "warning");
    EXPECT_STREQ(severityName(Severity::Error), "error");
}

TEST(SourceTexts, LinesWithCrlfEndingsAndNoFinalNewline) {
    SourceTexts src;
    src.add("f", "one\r\ntwo \\\r\n\r\nlast");
    EXPECT_EQ(src.line("f", 1), "one");
    EXPECT_EQ(src.line("f", 2), "two \\");
    EXPECT_EQ(src.line("f", 3), "");
    EXPECT_EQ(src.line("f", 4), "last");
    EXPECT_EQ(src.line("f", 5), "");
    EXPECT_EQ(src.line("f", 0), "");
    EXPECT_EQ(src.line("other", 1), "");
}

TEST(SourceTexts, KeepsTrailingBlanksAndTabs) {
    SourceTexts src;
    src.add("f", "a\\ \t\nb\n");
    EXPECT_EQ(src.line("f", 1), "a\\ \t");
    EXPECT_EQ(src.line("f", 2), "b");
}

TEST(Diagnostics, CountsBySeverity) {
    Diagnostics d;
    EXPECT_FALSE(d.hasErrors());
    d.warning("f", {1, 1}, "w1");
    d.note("f", {1, 1}, "n");
    EXPECT_FALSE(d.hasErrors());
    d.error("f", {2, 3}, "e");
    d.warning("f", {0, 0}, "w2");
    EXPECT_TRUE(d.hasErrors());
    EXPECT_EQ(d.errorCount(), 1);
    EXPECT_EQ(d.warningCount(), 2);
    ASSERT_EQ(d.all().size(), 4u);
    EXPECT_EQ(d.all()[2].severity, Severity::Error);
    EXPECT_EQ(d.all()[2].file, "f");
    EXPECT_EQ(d.all()[2].loc.line, 2);
    EXPECT_EQ(d.all()[2].loc.col, 3);
    EXPECT_EQ(d.all()[2].message, "e");
    d.clear();
    EXPECT_TRUE(d.all().empty());
}

}  // namespace
}  // namespace glimmer
