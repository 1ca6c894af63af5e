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
using glimmer_cli::writeRunawayScript;

TEST(CliTimeout, ARunawayShaderIsStoppedAndItsPassNamed) {
    TempDir dir;
    std::string script = writeRunawayScript(dir);
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
    auto r = runGlimmer({"-q", "check", writeRunawayScript(dir), "--backend", "osmesa", "--timeout", "20"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "stopped after"), 0) << r.err;
}

}  // namespace
