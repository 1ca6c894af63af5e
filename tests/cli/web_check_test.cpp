// `glimmer check --web`: every Program's shaders translated for WebGL 2, with
// no OpenGL context; what cannot run there is an error in Glimmer's usual
// form, at the user's line, and the exit code says so.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"
#include "common/test_folder.h"

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

// --list-inputs: after a clean check, every file the script reads, once
// each, in the order it names them (the lesson packer packs these); with
// an error, nothing (a lesson must not carry a script that fails). The
// same with and without --web.
TEST(CliWebCheck, ListInputsNamesEveryFileTheScriptReads) {
    const std::string want = "scripts/bloom.glib\ntextures/grid.bmp\nshaders/superblur.vert\nshaders/superblur.frag\n"
                             "shaders/bloom.vert\nshaders/bloom.frag\n";
    for (bool web : {true, false}) {
        std::vector<std::string> args = {"check", "--list-inputs", "scripts/bloom.glib"};
        if (web) args.insert(args.begin() + 1, "--web");
        if (!web) args.insert(args.begin() + 1, {"--backend", "osmesa"});
        auto r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.out, want) << (web ? "--web" : "osmesa");
    }
    auto broken = runGlimmer({"check", "--web", "--list-inputs", webData("broken.glib")});
    EXPECT_EQ(broken.exitCode, 1);
    EXPECT_EQ(broken.out, "");
}

// Every Program of the seed scripts translates, and the translation adds
// no message of its own: the web check says exactly what the desktop check
// on a real context says (the script's own warnings), nothing more.
TEST(CliWebCheck, TheSeedScriptsTranslate) {
    for (const char* script : {"scripts/bloom.glib", "scripts/superblur.glib", "tests/data/web/compat_scene.glib"}) {
        auto web = runGlimmer({"check", "--web", script});
        auto desktop = runGlimmer({"check", script, "--backend", "osmesa"});
        EXPECT_EQ(web.exitCode, 0) << script << "\n" << web.err;
        EXPECT_EQ(desktop.exitCode, 0) << script << "\n" << desktop.err;
        EXPECT_EQ(web.err, desktop.err) << script;
        EXPECT_EQ(web.out, "") << script;
    }
    // The script made for the translation (every compatibility built-in) is clean;
    // bloom.glib's warnings are its own lines, as written.
    EXPECT_EQ(runGlimmer({"check", "--web", "tests/data/web/compat_scene.glib"}).err, "");
    auto [orthoLine, ortho] = lineStarting("scripts/bloom.glib", "Ortho");
    EXPECT_EQ(runGlimmer({"check", "--web", "scripts/bloom.glib"}).err,
              "scripts/bloom.glib: warning: 5 uniforms on lines of their own were taken as part of their Program "
              "(glman needs a '\\'); -v to list them\n"
              "scripts/bloom.glib:" + std::to_string(orthoLine) + ":1: warning: degenerate Ortho -1. -1. 1. 1. (left == "
              "right): OpenGL rejects it and keeps the current projection, Ortho -3 3 -3 3\n" + ortho + "\n^\n");
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

// What glslang says as a warning stays a warning, at the user's line, with
// glslang's own words and not its "WARNING:" (issue 40's sampled mutant
// glslang_log.cpp:115 read every such line as an error): an extension the
// translator does not know is one warning, and the script checks clean.
TEST(CliWebCheck, AGlslangWarningIsAWarningAtItsLine) {
    glimmer::testing::TestFolder dir("web_warning");
    std::ofstream(dir.path / "s.glib") << "##OpenGL GLIB\nVertex v.vert\nFragment f.frag\nProgram P\nQuadXY 0 1\n";
    std::ofstream(dir.path / "v.vert") << "void main() { gl_Position = gl_Vertex; }\n";
    std::ofstream(dir.path / "f.frag") << "#version 120\n#extension GL_NV_made_up : enable\n"
                                          "void main() { gl_FragColor = vec4(1.); }\n";
    auto r = runGlimmer({"check", "--web", (dir.path / "s.glib").string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, (dir.path / "f.frag").string() +
                         ":2:1: warning: '#extension': extension not supported: GL_NV_made_up\n"
                         "#extension GL_NV_made_up : enable\n^\n");
}

TEST(CliWebCheck, TheDesktopCheckOfTheSameScriptsStillCompilesOnAContext) {
    // Without --web, a geometry shader is fine: the desktop has them, and
    // the check has nothing to say.
    auto r = runGlimmer({"check", webData("geometry.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    // It is really compiled there: a mistake in the geometry shader is the
    // driver's error at its line, where --web only says WebGL 2 has none.
    TempDir dir;
    for (const char* f : {"geometry.glib", "compat_pattern.vert", "compat_pattern.frag"})
        std::ofstream(dir.file(f)) << slurpFile(webData(f));
    std::string geom = slurpFile(webData("pass.geom"));
    const std::string good = "gl_Position = gl_in[i].gl_Position;";
    ASSERT_NE(geom.find(good), std::string::npos);
    geom.replace(geom.find(good), good.size(), "gl_Position = gl_in[i].gl_Positon;");
    std::ofstream(dir.file("pass.geom")) << geom;
    auto broken = runGlimmer({"check", dir.file("geometry.glib"), "--backend", "osmesa"});
    EXPECT_EQ(broken.exitCode, 1) << broken.err;
    EXPECT_EQ(broken.err.rfind(dir.file("pass.geom") + ":11:", 0), 0u) << broken.err;
    EXPECT_NE(broken.err.find(" [driver]\n        gl_Position = gl_in[i].gl_Positon;\n"), std::string::npos)
        << broken.err;
    auto web = runGlimmer({"check", "--web", dir.file("geometry.glib")});
    EXPECT_EQ(web.exitCode, 1) << web.err;
    EXPECT_EQ(web.err.find("pass.geom:11:"), std::string::npos) << web.err;
    EXPECT_NE(web.err.find("error: Program Passed cannot run in WebGL 2: its geometry shader 'pass.geom'"),
              std::string::npos)
        << web.err;
}

// GSTAP's aliases (aVertex for gl_Vertex, uModelViewProjectionMatrix for
// gl_ModelViewProjectionMatrix, ...) are for GSTAP Programs only: a shader of
// another Program may declare those names as its own.
TEST(CliWebCheck, AProgramWithoutGstapKeepsItsOwnNames) {
    TempDir dir;
    std::ofstream(dir.file("own.vert")) << "#version 330 compatibility\nuniform mat4 uModelViewProjectionMatrix;\n"
                                           "in vec4 aVertex;\nout vec2 vST;\nvoid main() {\n    vST = aVertex.xy;\n"
                                           "    gl_Position = uModelViewProjectionMatrix * aVertex;\n}\n";
    std::ofstream(dir.file("own.frag")) << "#version 330 compatibility\nin vec2 vST;\nvoid main() { gl_FragColor = "
                                           "vec4(vST, 0., 1.); }\n";
    std::ofstream(dir.file("own.glib")) << "Vertex own.vert\nFragment own.frag\nProgram Own\nQuadXY 0 1\n";
    auto r = runGlimmer({"check", "--web", dir.file("own.glib")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(CliWebCheck, HelpListsTheOption) {
    auto r = runGlimmer({"help", "check"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("--web"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace glimmer_cli
