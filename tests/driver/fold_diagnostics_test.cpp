// One mistake, one message (issue 19): a driver's log whose first error
// causes the rest prints the first with its line and caret, and one line
// counting the others; -v (no folding) prints them all.
#include <gtest/gtest.h>

#include "driver/error_cascades.h"
#include "driver/fold_diagnostics.h"

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

}  // namespace
}  // namespace glimmer
