// What a diagnostic may echo of hostile text: a window of the line, control
// characters escaped, and lines found through an index (never quadratic).
#include <chrono>

#include <gtest/gtest.h>

#include "lang/diagnostics.h"

namespace glimmer {
namespace {

TEST(DiagnosticLimits, AMegabyteLineIsShownAsAWindowAroundTheCaret) {
    std::string line(1000000, 'a');
    line[500000] = 'X';
    SourceTexts src;
    src.add("f", line + "\n");
    std::string out = formatDiagnostic({Severity::Error, "f", {1, 500001}, "bad"}, src);
    const std::string window = "..." + std::string(100, 'a') + "X" + std::string(99, 'a') + "...";
    EXPECT_EQ(out, "f:1:500001: error: bad\n" + window + "\n" + std::string(103, ' ') + "^");
}

TEST(DiagnosticLimits, ALongLineNearItsStartIsCutAtTheEnd) {
    SourceTexts src;
    src.add("f", std::string(300, 'b'));
    EXPECT_EQ(formatDiagnostic({Severity::Warning, "f", {1, 2}, "m"}, src),
              "f:1:2: warning: m\n" + std::string(200, 'b') + "...\n ^");
}

TEST(DiagnosticLimits, ControlCharactersAreEscapedInLinesAndMessages) {
    SourceTexts src;
    src.add("f", "Texture2D \x1b[2J 5\x07 x\n");
    std::string out = formatDiagnostic({Severity::Error, "f", {1, 19}, "'\x1b]0;pwned\x07' is odd"}, src);
    EXPECT_EQ(out, "f:1:19: error: '\\x1b]0;pwned\\x07' is odd\n"
                   "Texture2D \\x1b[2J 5\\x07 x\n"
                   "                        ^");
    EXPECT_EQ(out.find('\x1b'), std::string::npos);
}

TEST(DiagnosticLimits, LongMessagesAreCutPerLine) {
    std::string out = formatDiagnostic({Severity::Error, "", {0, 0}, std::string(500, 'm') + "\nshort"}, SourceTexts{});
    EXPECT_EQ(out, "error: " + std::string(200, 'm') + "...\nshort");
}

TEST(DiagnosticLimits, ManyDiagnosticsOnABigTextFormatInLinearTime) {
    std::string text;
    const int lines = 200000;
    for (int i = 0; i < lines; ++i) text += "Frobnicate 1 2 3\n";
    SourceTexts src;
    src.add("big.glib", text);
    auto t0 = std::chrono::steady_clock::now();
    size_t total = 0;
    for (int i = 1; i <= lines; i += 1) total += formatDiagnostic({Severity::Warning, "big.glib", {i, 1}, "m"}, src).size();
    EXPECT_GT(total, 0u);
    // Scanning from the top for each line took minutes here.
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
}

TEST(DiagnosticLimits, CountsAreKeptAsDiagnosticsAreAdded) {
    Diagnostics d;
    d.error("f", {}, "e");
    d.warning("f", {}, "w");
    d.note("f", {}, "n");
    EXPECT_EQ(d.errorCount(), 1);
    EXPECT_EQ(d.warningCount(), 1);
    d.clear();
    EXPECT_FALSE(d.hasErrors());
    EXPECT_EQ(d.warningCount(), 0);
}

}  // namespace
}  // namespace glimmer
