// --timeout: a runaway shader is stopped, the pass still drawing is named,
// and a script that finishes in time is untouched by the watchdog.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>

#include "run_glimmer.h"

namespace {

using glimmer_cli::countOf;
using glimmer_cli::runGlimmer;
using glimmer_cli::TempDir;

// Forty sines an iteration, 60000 iterations (llvmpipe caps a loop at 65535),
// for every pixel of a 256x256 screen: minutes on llvmpipe, and no compiler
// can fold it away (each sine feeds the next). The runaway pass is the
// second: the first, into unit 6, is quick.
std::string writeRunaway(const TempDir& dir) {
    std::ofstream(dir.file("st.vert")) << "#version 330 compatibility\nout vec2 vST;\nvoid main() {\n"
                                          "    vST = gl_MultiTexCoord0.st;\n"
                                          "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n}\n";
    std::ofstream(dir.file("quick.frag")) << "#version 330 compatibility\nin vec2 vST;\n"
                                             "void main() { gl_FragColor = vec4(vST, 0., 1.); }\n";
    std::string body;
    for (int k = 0; k < 40; ++k)
        body += "        a = sin(a * 1.0001 + float(i) * 1e-5 + vST.s + " + std::to_string(k) + ".0);\n";
    std::ofstream(dir.file("slow.frag")) << "#version 330 compatibility\nuniform sampler2D Quick;\nin vec2 vST;\n"
                                            "void main() {\n    float a = texture(Quick, vST).r;\n"
                                            "    for (int i = 0; i < 60000; ++i) {\n" << body
                                         << "    }\n    gl_FragColor = vec4(a, 0., 0., 1.);\n}\n";
    std::ofstream(dir.file("slow.glib")) << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nTexture2D 6 64 64\n"
                                            "Vertex st.vert\nRenderToTexture 6\nFragment quick.frag\nProgram Quick\n"
                                            "QuadXY 0 1\nRenderToTexture\nFragment slow.frag\nProgram Slow Quick 6\n"
                                            "QuadXY 0 1\n";
    return dir.file("slow.glib");
}

TEST(CliTimeout, ARunawayShaderIsStoppedAndItsPassNamed) {
    TempDir dir;
    std::string script = writeRunaway(dir);
    auto t0 = std::chrono::steady_clock::now();
    auto r = runGlimmer({"render", script, "--size", "256x256", "--backend", "osmesa", "--timeout", "2", "-o",
                         dir.file("o.png")}, 60);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_LT(seconds, 20.0);  // stopped near 2 s, not after the minutes the shader needs
    // The screen pass is known by its RenderToTexture line (line 9).
    EXPECT_EQ(r.err, script + ":9:1: error: stopped after 2 s (--timeout 2): the pass that starts here was still "
                              "drawing\nRenderToTexture\n^\n") << r.err;
    std::ifstream written(dir.file("o.png"));
    EXPECT_FALSE(written.good()) << "a stopped render writes no picture";
}

TEST(CliTimeout, AScriptThatFinishesInTimeIsUntouched) {
    TempDir dir;
    auto plain = runGlimmer({"-q", "render", "scripts/bloom.glib", "--size", "64x64", "--backend", "osmesa", "-o",
                             dir.file("plain.png")});
    auto watched = runGlimmer({"-q", "render", "scripts/bloom.glib", "--size", "64x64", "--backend", "osmesa",
                               "--timeout", "60", "-o", dir.file("watched.png")});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    ASSERT_EQ(watched.exitCode, 0) << watched.err;
    EXPECT_EQ(watched.err, plain.err);
    std::ifstream a(dir.file("plain.png"), std::ios::binary), b(dir.file("watched.png"), std::ios::binary);
    std::string pa((std::istreambuf_iterator<char>(a)), {}), pb((std::istreambuf_iterator<char>(b)), {});
    EXPECT_FALSE(pa.empty());
    EXPECT_EQ(pa, pb);
}

TEST(CliTimeout, CheckDrawsNothingSoTheRunawayShaderPasses) {
    TempDir dir;
    auto r = runGlimmer({"-q", "check", writeRunaway(dir), "--backend", "osmesa", "--timeout", "20"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "stopped after"), 0) << r.err;
}

}  // namespace
