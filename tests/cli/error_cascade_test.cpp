// One mistake, one message (issue 19): one undeclared sampler makes Mesa
// reject the texture() call and list every overload it tried. By default the
// first error is printed with its line and caret and the rest counted in one
// line; -v prints them all.
#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {

TEST(CliErrorCascade, AnUndeclaredNameIsOneErrorAndACount) {
    const std::string shader = cliData("undeclared.frag");
    auto all = runGlimmer({"-v", "check", cliData("undeclared.glib"), "--backend", "osmesa"});
    EXPECT_EQ(all.exitCode, 1) << all.err;
    // Every error the driver gave, each with its source line and caret.
    const int errors = countOf(all.err, ": error: "), warnings = countOf(all.err, ": warning: ");
    ASSERT_GT(errors, 2) << all.err;
    // The summary counts causes, not the driver's lines (issue 31): one
    // mistake is one error, with -v as without.
    const std::string summary = "1 error, 0 warnings\n";
    EXPECT_EQ(all.err.substr(all.err.size() - summary.size()), summary) << all.err;
    // Mesa's own words for what followed: the overloads it tried, and the
    // variable whose initialiser failed, used uninitialised.
    EXPECT_NE(all.err.find(": error: vec4 texture(sampler2D, vec2) [driver]\n"), std::string::npos) << all.err;

    auto r = runGlimmer({"check", cliData("undeclared.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    std::string more = std::to_string(errors - 1) + " more errors";
    if (warnings > 0) more += " and " + std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings");
    EXPECT_EQ(r.err, shader + ":9:22: error: `uImagee' undeclared [driver]\n"
                               "    vec3 rgb = texture( uImagee, vST ).rgb;\n"
                               "                     ^\n" +
                         shader + ":9: note: " + more + " follow from this one; -v shows them\n" + summary);
    // -q: errors only, folded the same way.
    auto quiet = runGlimmer({"-q", "check", cliData("undeclared.glib"), "--backend", "osmesa"});
    EXPECT_EQ(countOf(quiet.err, ": error: "), 1) << quiet.err;
    EXPECT_EQ(countOf(quiet.err, " follow from this one; -v shows them\n"), 1) << quiet.err;
    EXPECT_EQ(quiet.err.substr(quiet.err.size() - 8), "1 error\n") << quiet.err;
}

// A shader named but not found is one error where it is named; the Program
// after it is not also said to have no shaders.
TEST(CliErrorCascade, AMissingShaderIsOneErrorWhereItIsNamed) {
    const std::string script = cliData("missing_shaders.glib");
    auto r = runGlimmer({"check", script, "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(countOf(r.err, ": error: cannot find shader "), 2) << r.err;
    EXPECT_NE(r.err.find(script + ":4:8: error: cannot find shader 'lost.vert'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(script + ":5:10: error: cannot find shader 'lost.frag'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("has no shaders"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\n2 errors, 0 warnings\n"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace glimmer_cli
