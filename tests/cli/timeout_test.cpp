// --timeout: a runaway shader is stopped, the pass still drawing is named,
// and a script that finishes in time is untouched by the watchdog.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

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

// The passes the renderer announced after glimmer's last look are still in
// the pipe when the time runs out: they are read before the message is
// made. Shown by stopping glimmer (SIGSTOP) while its renderer announces
// both passes and starts the runaway one, and letting it go on only after
// its --timeout has passed: it names the runaway pass, not an earlier one
// and not "while loading".
TEST(CliTimeout, PassesAnnouncedWhileGlimmerWasNotLookingAreRead) {
    TempDir dir, logs;
    const std::string script = writeRunawayScript(dir);
    const pid_t parent = glimmer_cli::startGlimmer({"render", script, "--size", "256x256", "--backend", "osmesa",
                                                    "--timeout", "1", "-o", dir.file("o.png")},
                                                   logs.path().string());
    const std::vector<pid_t> kids = glimmer_cli::waitForChildren(parent, 1, 10);
    ::kill(parent, SIGSTOP);
    std::this_thread::sleep_for(std::chrono::seconds(10));  // the renderer loads, draws pass 1, starts pass 2 (under 1 s alone)
    ::kill(parent, SIGCONT);
    int status = 0;
    ::waitpid(parent, &status, 0);
    ASSERT_FALSE(kids.empty()) << "no renderer started: " << glimmer_cli::readAll(logs.file("stderr"));
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
    EXPECT_EQ(glimmer_cli::readAll(logs.file("stderr")),
              script + ":9:1: error: stopped after 1 s (--timeout 1): the pass that starts here was still drawing\n"
                       "RenderToTexture\n^\n");
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
