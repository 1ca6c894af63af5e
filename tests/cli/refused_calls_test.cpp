// A call the OpenGL driver refuses does nothing, and glGetError is the only
// sign of it: render and batch read it after drawing and warn
// (gl/gl_api.h's refusedCallWarning). Glimmer's own uploads must never be
// refused, whatever uniform types a script sets; a script that makes the
// driver refuse its draw is told so.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_glimmer.h"
#include "image/image.h"

using namespace glimmer_cli;

namespace {

const char* kVert = "#version 330 compatibility\nout vec2 vST;\n"
                    "void main() { vST = gl_MultiTexCoord0.st; gl_Position = ftransform(); }\n";
const char* kView = "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\n";

// Each integer and bool shape a Program line sets, read into the colour:
// uN 3 of 4 in red; uV2.y + uV3.z + uV4.w = 2 + 3 + 4 = 9 of 12 in green;
// uB in blue. An upload the driver refused would leave its uniform 0 or
// warn (a scalar sent as a vector is refused, leaving the value set).
TEST(CliRefusedCalls, IntAndBoolUniformsOfEverySizeArriveWithNoCallRefused) {
    TempDir dir;
    std::ofstream(dir.file("a.vert")) << kVert;
    std::ofstream(dir.file("a.frag"))
        << "#version 330 compatibility\nuniform int uN;\nuniform ivec2 uV2;\nuniform ivec3 uV3;\n"
           "uniform ivec4 uV4;\nuniform bool uB;\nin vec2 vST;\n"
           "void main() { gl_FragColor = vec4(float(uN) / 4., float(uV2.y + uV3.z + uV4.w) / 12., uB ? 1. : 0., 1.); }\n";
    std::ofstream(dir.file("s.glib")) << kView << "Vertex a.vert\nFragment a.frag\n"
                                      << "Program P uN <0 3 4> uV2 [1 2] uV3 [1 2 3] uV4 [1 2 3 4] uB <true>\n"
                                         "QuadXY 0 1\n";
    for (const char* command : {"render", "batch"}) {
        SCOPED_TRACE(command);
        const bool batch = std::string(command) == "batch";
        TempDir out;  // batch names its one picture after the script's path
        auto r = runGlimmer({command, dir.file("s.glib"), "-o", batch ? out.path().string() : out.file("o.png"),
                             "--size", "16x16", "--backend", "osmesa"});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
        std::string png;
        for (const auto& e : std::filesystem::directory_iterator(out.path())) png = e.path().string();
        const glimmer::Image img = loadPicture(png);
        ASSERT_EQ(img.u8.size(), 16u * 16u * 4u);
        EXPECT_EQ(int(img.u8[(8 * 16 + 8) * 4 + 0]), 191);  // 0.75 of 255
        EXPECT_EQ(int(img.u8[(8 * 16 + 8) * 4 + 1]), 191);
        EXPECT_EQ(int(img.u8[(8 * 16 + 8) * 4 + 2]), 255);
    }
}

// Two kinds of sampler on one unit: OpenGL refuses the draw
// (GL_INVALID_OPERATION). The plan's warning says why it will; the driver's
// refusal is then said too, after the frame.
TEST(CliRefusedCalls, ADrawTheDriverRefusedIsWarnedAfterTheFrame) {
    TempDir dir;
    std::ofstream(dir.file("a.vert")) << kVert;
    std::ofstream(dir.file("a.frag"))
        << "#version 330 compatibility\nuniform sampler2D uA;\nuniform sampler3D uB;\nin vec2 vST;\n"
           "void main() { gl_FragColor = vec4(texture(uA, vST).rgb + texture(uB, vec3(vST, .5)).rgb, 1.); }\n";
    const std::string script = dir.file("s.glib");
    std::ofstream(script) << kView << "Texture2D 5 16 16\nVertex a.vert\nFragment a.frag\nProgram P uA 5 uB 5\n"
                                      "QuadXY 0 1\n";
    auto r = runGlimmer({"render", script, "-o", dir.file("o.png"), "--size", "16x16", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string line = "Program P uA 5 uB 5\n^\n";
    EXPECT_EQ(r.err, script + ":6:1: warning: Program P: sampler2D uA and sampler3D uB both read unit 5; OpenGL draws "
                              "nothing with samplers of two kinds on one unit: give them different units\n" + line +
                         script + ":6:1: warning: Program P: sampler3D uB reads unit 5, which holds a 2-D texture "
                                  "(line 3); it reads black\n" + line +
                         "glimmer: warning: the OpenGL driver refused a call while drawing (GL_INVALID_OPERATION, "
                         "0x0502): a step of the picture may be missing\n"
                         "wrote " + dir.file("o.png") + " (16x16)\n");
    // -q: errors only.
    r = runGlimmer({"-q", "render", script, "-o", dir.file("o.png"), "--size", "16x16", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.err, "");
    // batch says it where it says a script's warnings: the report's line for
    // the script (stderr carries only failures); under -q not there either.
    for (const bool quiet : {false, true}) {
        SCOPED_TRACE(quiet ? "batch -q" : "batch");
        std::vector<std::string> args = {"batch", script, "-o", dir.file("out"), "--report", dir.file("r.jsonl"),
                                         "--size", "16x16", "--backend", "osmesa"};
        if (quiet) args.insert(args.begin(), "-q");
        r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        const auto line = nlohmann::json::parse(readAll(dir.file("r.jsonl")), nullptr, false);
        const std::string said = line.value("diagnostics", "?");
        const std::string warning = "glimmer: warning: the OpenGL driver refused a call while drawing "
                                    "(GL_INVALID_OPERATION, 0x0502): a step of the picture may be missing\n";
        EXPECT_EQ(said.find(warning) != std::string::npos, !quiet) << said;
    }
}

}  // namespace
