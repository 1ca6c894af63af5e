// `glimmer check --web`: every Program's shaders translated for WebGL 2, with
// no OpenGL context; what cannot run there is an error in Glimmer's usual
// form, at the user's line, and the exit code says so.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {

std::string webData(const std::string& name) { return "tests/data/web/" + name; }

std::string slurpFile(const std::string& path) {
    std::ifstream in(std::string(GLIMMER_SOURCE_DIR) + "/" + path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The 1-based line of the first line of `path` that starts with `start`, and that line.
std::pair<int, std::string> lineStarting(const std::string& path, const std::string& start) {
    std::istringstream in(slurpFile(path));
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        if (line.rfind(start, 0) == 0) return {n, line};
    }
    ADD_FAILURE() << path << " has no line starting " << start;
    return {0, ""};
}

TEST(CliWebCheck, TheSeedScriptsTranslate) {
    for (const char* script : {"scripts/bloom.glib", "scripts/superblur.glib", "tests/data/web/compat_scene.glib"}) {
        auto r = runGlimmer({"check", "--web", script});
        EXPECT_EQ(r.exitCode, 0) << script << "\n" << r.err;
        EXPECT_EQ(r.err.find("error"), std::string::npos) << script << "\n" << r.err;
    }
}

TEST(CliWebCheck, AGeometryShaderIsOneErrorAtItsProgramsLine) {
    auto r = runGlimmer({"check", "--web", webData("geometry.glib")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    auto [line, text] = lineStarting(webData("geometry.glib"), "Program Passed");
    const std::string expected = webData("geometry.glib") + ":" + std::to_string(line) +
                                 ":1: error: Program Passed cannot run in WebGL 2: its geometry shader 'pass.geom' "
                                 "cannot be translated; WebGL 2 has no geometry shaders (GLSL ES 3.00 has only "
                                 "vertex and fragment shaders)\n" + text + "\n^\n1 error, 0 warnings\n";
    EXPECT_EQ(r.err, expected);
}

TEST(CliWebCheck, AShaderErrorPointsAtTheShadersLineAndColumn) {
    auto r = runGlimmer({"check", "--web", webData("broken.glib")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    auto [line, text] = lineStarting(webData("broken.frag"), "    gl_FragColor");
    const int col = int(text.find("stripe")) + 1;
    const std::string at = webData("broken.frag") + ":" + std::to_string(line) + ":" + std::to_string(col) +
                           ": error: 'stripe': undeclared identifier\n" + text + "\n";
    EXPECT_NE(r.err.find(at), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("glimmer_"), std::string::npos) << "the user never wrote the stand-ins:\n" << r.err;
}

TEST(CliWebCheck, TheDesktopCheckOfTheSameScriptsStillCompilesOnAContext) {
    // Without --web, a geometry shader is fine: the desktop has them.
    auto r = runGlimmer({"check", webData("geometry.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(CliWebCheck, HelpListsTheOption) {
    auto r = runGlimmer({"help", "check"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("--web"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace glimmer_cli
