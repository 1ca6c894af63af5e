// Problems in scripts and shaders: exit code 1 for errors, 0 for warnings,
// and diagnostics that point at the file and line the user wrote.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

RunResult renderData(const std::string& script, const TempDir& dir, const std::string& out = "out.png") {
    return runGlimmer({"render", cliData(script), "-o", dir.file(out), "--size", "32x32", "--backend", "osmesa"});
}

TEST(CliScriptErrors, ShaderCompileErrorNamesTheShaderFileAndLine) {
    TempDir dir;
    auto r = renderData("broken.glib", dir);
    ASSERT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const std::string at = cliData("broken.frag") + ":7:";
    ASSERT_NE(r.err.find(at), std::string::npos) << r.err;
    // The diagnostic is an error, followed by the shader's own line 7.
    std::string rest = r.err.substr(r.err.find(at) + at.size());
    EXPECT_NE(rest.find(": error: "), std::string::npos) << r.err;
    EXPECT_NE(rest.find("notDeclared"), std::string::npos) << r.err;
    EXPECT_NE(rest.find("\n    gl_FragColor = vec4( notDeclared, 0., 0., 1. );\n"), std::string::npos) << r.err;
    // Every message about the shader is on line 7.
    EXPECT_EQ(countOf(r.err, cliData("broken.frag") + ":"), countOf(r.err, at)) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(CliScriptErrors, CheckFindsTheShaderErrorAndRendersNothing) {
    TempDir dir;
    auto before = fs::exists(fs::path(GLIMMER_SOURCE_DIR) / "out.png");
    auto r = runGlimmer({"check", cliData("broken.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(cliData("broken.frag") + ":7:"), std::string::npos) << r.err;
    // How many messages the compiler gives varies; the summary counts them.
    EXPECT_TRUE(r.err.find(" error, 0 warnings\n") != std::string::npos ||
                r.err.find(" errors, 0 warnings\n") != std::string::npos)
        << r.err;
    EXPECT_EQ(fs::exists(fs::path(GLIMMER_SOURCE_DIR) / "out.png"), before);
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(CliScriptErrors, MissingTextureSaysWhereItLooked) {
    TempDir dir;
    auto r = renderData("missing_texture.glib", dir);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const std::string folder = cliData("");
    const std::string data = fs::path(folder).parent_path().parent_path().string();  // tests/data
    EXPECT_EQ(r.err, cliData("missing_texture.glib") +
                         ":2:13: error: cannot find texture 'nothere.bmp' (looked in " + data + "/cli, " + data +
                         "/shaders, " + data + "/textures)\n"
                         "Texture2D 5 nothere.bmp\n"
                         "            ^\n"
                         "1 error, 0 warnings\n");
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(CliScriptErrors, MissingTextureAlsoLooksInIncludeFolders) {
    TempDir dir;
    auto r = runGlimmer({"check", cliData("missing_texture.glib"), "-I", dir.path().string(), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(dir.path().string() + ")"), std::string::npos) << r.err;
}

TEST(CliScriptErrors, UnknownCommandIsOnlyAWarning) {
    TempDir dir;
    auto r = renderData("unknown_command.glib", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, cliData("unknown_command.glib") +
                         ":2:1: warning: unknown command 'Frobnicate'; line ignored\n"
                         "Frobnicate 1 2 3\n"
                         "^\n"
                         "wrote " + dir.file("out.png") + " (32x32)\n");
    unsigned w = 0, h = 0;
    ASSERT_TRUE(readPngSize(dir.file("out.png"), w, h));
    EXPECT_EQ(w, 32u);
    EXPECT_EQ(h, 32u);
}

TEST(CliScriptErrors, MalformedRangeIsAnError) {
    TempDir dir;
    auto r = renderData("bad_range.glib", dir);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, cliData("bad_range.glib") +
                         ":4:22: error: uniform 'uLevel': a range needs 3 values <min current max>, got 2 <0 1>\n"
                         "Program Solid uLevel <0 1>\n"
                         "                     ^\n"
                         "1 error, 0 warnings\n");
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(CliScriptErrors, GstapNamesCompileAndRender) {
    TempDir dir;
    auto r = renderData("gstap.glib", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "error"), 0) << r.err;
    unsigned w = 0, h = 0;
    ASSERT_TRUE(readPngSize(dir.file("out.png"), w, h)) << r.err;
    EXPECT_EQ(w, 32u);
    EXPECT_EQ(h, 32u);
}

// The control for the test above: the same shader without GSTAP fails, so
// the names really come from the prelude.
TEST(CliScriptErrors, WithoutGstapTheNewNamesAreUnknown) {
    TempDir dir;
    auto r = renderData("no_gstap.glib", dir);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(cliData("gstap.vert") + ":6:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("aVertex"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(CliScriptErrors, ShaderErrorAfterTheGstapPreludeKeepsItsLine) {
    TempDir dir;
    auto r = renderData("gstap_broken.glib", dir);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const std::string at = cliData("gstap_broken.frag") + ":9:";
    EXPECT_NE(r.err.find(at), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("stillNotDeclared"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\n    gl_FragColor = vec4( uLevel * stillNotDeclared, 0., 0., 1. );\n"), std::string::npos)
        << r.err;
    EXPECT_EQ(countOf(r.err, cliData("gstap_broken.frag") + ":"), countOf(r.err, at)) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

// A statement without its ';' (issue 39): every compiler reports the next
// line, where the next statement starts; the error is marked at the end of
// the line that lacks it, as clang marks it, and the driver's place is a
// note. Mesa's words on the desktop, glslang's for the page (check --web).
TEST(CliScriptErrors, AMissingSemicolonIsMarkedAtTheEndOfItsOwnLine) {
    TempDir dir;
    const fs::path src(GLIMMER_SOURCE_DIR);
    fs::copy_file(src / "scripts/bloom.glib", dir.file("bloom.glib"));
    for (auto f : {"superblur.vert", "superblur.frag", "bloom.vert"}) fs::copy_file(src / "shaders" / f, dir.file(f));
    fs::copy_file(src / "textures/grid.bmp", dir.file("grid.bmp"));
    std::string frag = readAll(src / "shaders/bloom.frag");
    const std::string line12 = "    vec3 rgbblur = texture( BlurUnit, vST ).rgb;";
    ASSERT_NE(frag.find(line12 + "\n"), std::string::npos);
    frag.replace(frag.find(line12), line12.size(), line12.substr(0, line12.size() - 1));
    writeFile(dir, "bloom.frag", frag);
    const std::string at = dir.file("bloom.frag");
    const std::string mark = "    vec3 rgbblur = texture( BlurUnit, vST ).rgb\n" + std::string(47, ' ') + "^\n";

    auto r = runGlimmer({"render", dir.file("bloom.glib"), "-o", dir.file("x.png"), "--size", "32x32", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(at + ":12:48: error: syntax error, unexpected NEW_IDENTIFIER, expecting ',' or ';' [driver]\n" + mark),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find(at + ":13:2: note: the next statement starts here\n"), std::string::npos) << r.err;

    auto web = runGlimmer({"check", "--web", dir.file("bloom.glib")});
    EXPECT_EQ(web.exitCode, 1) << web.err;
    EXPECT_NE(web.err.find(at + ":12:48: error: syntax error, unexpected IDENTIFIER, expecting COMMA or SEMICOLON\n" + mark),
              std::string::npos) << web.err;
    EXPECT_NE(web.err.find(at + ":13:5: note: the next statement starts here\n"), std::string::npos) << web.err;
}

}  // namespace
}  // namespace glimmer_cli
