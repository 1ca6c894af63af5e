// One mistake, one message (issue 19): a driver's log whose first error
// causes the rest prints the first with its line and caret, and one line
// counting the others; -v (no folding) prints them all.
#include <gtest/gtest.h>

#include "pipeline/error_cascades.h"
#include "pipeline/fold_diagnostics.h"

namespace glimmer {
namespace {

Diagnostic driverError(int line, int col, const std::string& message) {
    Diagnostic d;
    d.file = "shaders/glow.frag";
    d.loc = {line, col};
    d.message = message;
    d.fromDriver = true;
    return d;
}

// What Mesa says about `texture( uImagee, vST )` with uImagee undeclared: the
// name, then the call it poisoned and every overload it tried (cut to three
// here), then the assignment of the failed call, then the same name again.
std::vector<Diagnostic> undeclaredSampler() {
    return {
        driverError(6, 23, "`uImagee' undeclared"),
        driverError(6, 15, "no matching function for call to `texture(error, vec2)'; candidates are:"),
        driverError(6, 15, "vec4 texture(sampler1D, float)"),
        driverError(6, 15, "vec4 texture(sampler2D, vec2)"),
        driverError(6, 15, "vec4 texture(sampler3D, vec3)"),
        driverError(7, 5, "`uImagee' undeclared"),
    };
}

SourceTexts glowSource() {
    SourceTexts s;
    s.add("shaders/glow.frag", "#version 330 compatibility\nuniform sampler2D uImage;\nin vec2 vST;\nvoid main()\n{\n"
                               "    vec3 rgb = texture( uImagee, vST ).rgb;\n    uImagee;\n    gl_FragColor = "
                               "vec4(rgb, 1.);\n}\n");
    return s;
}

TEST(ErrorCascades, ErrorsOnTheFirstErrorsLineOrOfItsFailedTypeFollowFromIt) {
    EXPECT_EQ(errorCauses(undeclaredSampler()), (std::vector<int>{-1, 0, 0, 0, 0, 0}));
}

TEST(ErrorCascades, TheFirstErrorIsShownWithItsLineAndTheRestCounted) {
    size_t notShown = 0;
    auto lines = foldDiagnostics(undeclaredSampler(), glowSource(), true, true, true, 100, notShown);
    EXPECT_EQ(lines, (std::vector<std::string>{
                         "shaders/glow.frag:6:23: error: `uImagee' undeclared [driver]\n"
                         "    vec3 rgb = texture( uImagee, vST ).rgb;\n"
                         "                      ^\n"
                         "shaders/glow.frag:6: note: 5 more errors follow from this one; -v shows them"}));
    // -v: every error, each with its line.
    lines = foldDiagnostics(undeclaredSampler(), glowSource(), false, false, true, 100, notShown);
    EXPECT_EQ(lines.size(), 6u);
}

// Mesa then warns that the variable whose initialiser failed is used
// uninitialised: the same mistake again, counted with the errors.
TEST(ErrorCascades, TheDriversWarningsAfterTheErrorAreCountedToo) {
    std::vector<Diagnostic> all = undeclaredSampler();
    Diagnostic w = driverError(8, 26, "`rgb' used uninitialized");
    w.severity = Severity::Warning;
    all.push_back(w);
    Diagnostic script;  // the script's own warnings stay
    script.severity = Severity::Warning;
    script.file = "glow.glib";
    script.loc = {2, 1};
    script.message = "unknown command 'Foo'; line ignored";
    all.push_back(script);
    EXPECT_EQ(errorCauses(all), (std::vector<int>{-1, 0, 0, 0, 0, 0, 0, -1}));
    size_t notShown = 0;
    auto lines = foldDiagnostics(all, glowSource(), true, true, true, 100, notShown);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NE(lines[0].find("\nshaders/glow.frag:6: note: 5 more errors and 1 warning follow from this one; -v shows them"),
              std::string::npos)
        << lines[0];
    EXPECT_EQ(lines[1].rfind("glow.glib:2:1: warning: unknown command 'Foo'", 0), 0u) << lines[1];
}

TEST(ErrorCascades, SeparateMistakesStaySeparate) {
    // Another line, another message: a mistake of its own. Script errors
    // (not the driver's) never fold, even on one line.
    std::vector<Diagnostic> all = {driverError(6, 23, "`uImagee' undeclared"),
                                   driverError(9, 5, "`vSt' undeclared")};
    Diagnostic script;
    script.file = "glow.glib";
    script.loc = {3, 11};
    script.message = "'<' is never closed (missing '>'); command 'Program' ignored";
    all.push_back(script);
    script.loc = {3, 20};
    all.push_back(script);
    EXPECT_EQ(errorCauses(all), (std::vector<int>{-1, -1, -1, -1}));
    // One follower: singular.
    size_t notShown = 0;
    auto lines = foldDiagnostics({driverError(6, 23, "`uImagee' undeclared"), driverError(6, 15, "type error")},
                                 glowSource(), true, true, true, 100, notShown);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("\nshaders/glow.frag:6: note: 1 more error follows from this one; -v shows it"),
              std::string::npos)
        << lines[0];
}

Diagnostic inFile(const std::string& file, int line, const std::string& message, bool fromDriver = true,
                  Severity severity = Severity::Error) {
    Diagnostic d = driverError(line, 1, message);
    d.file = file;
    d.fromDriver = fromDriver;
    d.severity = severity;
    return d;
}

// Issue 26: a cascade stays in its file. The same line number (and even the
// same message) in the program's other stage is a mistake of its own.
TEST(ErrorCascades, TheSameLineOfAnotherFileIsAnotherMistake) {
    std::vector<Diagnostic> all = {inFile("a.vert", 5, "`uTime' undeclared"), inFile("a.frag", 5, "`vColour' undeclared"),
                                   inFile("a.frag", 7, "`uTime' undeclared")};
    EXPECT_EQ(errorCauses(all), (std::vector<int>{-1, -1, -1}));
    size_t notShown = 0;
    auto lines = foldDiagnostics(all, SourceTexts{}, true, true, true, 100, notShown);
    EXPECT_EQ(lines, (std::vector<std::string>{"a.vert:5:1: error: `uTime' undeclared [driver]",
                                               "a.frag:5:1: error: `vColour' undeclared [driver]",
                                               "a.frag:7:1: error: `uTime' undeclared [driver]"}));
}

// Only the driver's errors start a run: one of Glimmer's own errors about a
// shader (a translation's, a sandbox's) never hides the driver's after it,
// and Glimmer's own notes about the shader (the false-alarm note on a
// driver's "used uninitialized") are never hidden under a driver's error.
TEST(ErrorCascades, OnlyTheDriversOwnMessagesFollow) {
    std::vector<Diagnostic> all = {inFile("glow.frag", 6, "`uImagee' undeclared", false),
                                   inFile("glow.frag", 6, "`uImagee' undeclared")};
    EXPECT_EQ(errorCauses(all), (std::vector<int>{-1, -1}));
    all = {inFile("glow.frag", 6, "`uImagee' undeclared"),
           inFile("glow.frag", 8, "the driver's warning is a false alarm", false, Severity::Note),
           inFile("glow.frag", 9, "`x' used uninitialized", true, Severity::Warning)};
    EXPECT_EQ(errorCauses(all), (std::vector<int>{-1, -1, 0}));
}

// An error on another line that names Mesa's `error` type (an expression
// that already failed) follows from the first error, in each of its spellings.
TEST(ErrorCascades, AnErrorNamingTheFailedTypeOnAnotherLineFollows) {
    for (const char* m : {"no matching function for call to `max(error, float)'",
                          "operands of type error and float cannot be added", "cannot convert from `error' to `vec3'",
                          "wrong arguments (error)"}) {
        SCOPED_TRACE(m);
        EXPECT_EQ(errorCauses({driverError(6, 23, "`uImagee' undeclared"), driverError(9, 5, m)}),
                  (std::vector<int>{-1, 0}));
    }
    // A message that merely contains the word: a mistake of its own.
    EXPECT_EQ(errorCauses({driverError(6, 23, "`uImagee' undeclared"), driverError(9, 5, "syntax error, unexpected ')'")}),
              (std::vector<int>{-1, -1}));
}

TEST(FoldDiagnostics, AKindIsTheMessageWithoutItsNamesAndNumbers) {
    EXPECT_EQ(diagnosticKind("uniform 'uA' is on line 12 of Program 'P', value 0.5"),
              "uniform '?' is on line # of Program '?', value #");
    EXPECT_EQ(diagnosticKind("an 'unclosed quote 3"), "an 'unclosed quote #");
}

TEST(FoldDiagnostics, TwoWarningsOfOneKindInOneFileAreOneLine) {
    std::vector<Diagnostic> all = {
        inFile("s.glib", 3, "uniform 'uA' is not used by the shaders of Program P (not declared)", false,
               Severity::Warning),
        inFile("s.glib", 9, "uniform 'uB' is not used by the shaders of Program P (not declared)", false,
               Severity::Warning),
        inFile("s.glib", 4, "texture 2 is 300 wide", false, Severity::Warning),
        inFile("s.glib", 5, "texture 3 is 1 wide", false, Severity::Warning)};
    size_t notShown = 0;
    EXPECT_EQ(foldDiagnostics(all, SourceTexts{}, true, true, true, 100, notShown),
              (std::vector<std::string>{
                  "s.glib: warning: 2 uniforms are not used by the shaders of their Program; -v to list them",
                  "s.glib: warning: 2 warnings like this one (line 4 first): texture 2 is 300 wide; -v to list them"}));
    // -v: each on its own; -q: none.
    EXPECT_EQ(foldDiagnostics(all, SourceTexts{}, false, true, true, 100, notShown).size(), 4u);
    EXPECT_TRUE(foldDiagnostics(all, SourceTexts{}, true, true, false, 100, notShown).empty());
}

TEST(FoldDiagnostics, WarningsOfTwoFilesAreNotFoldedTogether) {
    std::vector<Diagnostic> all = {inFile("a.glib", 3, "texture 2 is 300 wide", false, Severity::Warning),
                                   inFile("b.glib", 3, "texture 2 is 300 wide", false, Severity::Warning)};
    size_t notShown = 0;
    EXPECT_EQ(foldDiagnostics(all, SourceTexts{}, true, true, true, 100, notShown),
              (std::vector<std::string>{"a.glib:3:1: warning: texture 2 is 300 wide",
                                        "b.glib:3:1: warning: texture 2 is 300 wide"}));
}

TEST(FoldDiagnostics, PastTheLimitTheRestAreCounted) {
    std::vector<Diagnostic> all;
    for (int line = 1; line <= 5; ++line) all.push_back(inFile("s.glib", line, "bad " + std::string(1, char('a' + line)), false));
    size_t notShown = 0;
    auto lines = foldDiagnostics(all, SourceTexts{}, true, true, true, 3, notShown);
    EXPECT_EQ(lines, (std::vector<std::string>{"s.glib:1:1: error: bad b", "s.glib:2:1: error: bad c",
                                               "s.glib:3:1: error: bad d"}));
    EXPECT_EQ(notShown, 2u);
}

}  // namespace
}  // namespace glimmer
