// A picture drawn on a context the GPU lost or reset is not the script's
// (NVIDIA reads back zeros): `glimmer render` says why, exits 1 and writes
// no file, as batch's workers do (docs/RELIABILITY.md). llvmpipe never
// loses a context, so the loss is put in through GLIMMER_TEST_FAULT
// (src/process/test_fault.h), which stands in for contextFailure's answer.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

using namespace glimmer_cli;
namespace fs = std::filesystem;

namespace {

TEST(CliRenderLostContext, APictureLostToAResetIsAnErrorAndNoFile) {
    TempDir dir;
    const std::string script = writeSolid(dir, "lost.glib", 1);
    const std::vector<std::string> args = {"render", script, "-o", dir.file("o.png"), "--size", "16x16",
                                           "--backend", "osmesa"};
    {
        TestFaultEnv fault("reset:lost.glib:");
        auto r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_EQ(r.err, "glimmer: error: the GPU was reset by another process while this script drew "
                         "(GLIMMER_TEST_FAULT)\n");
        EXPECT_FALSE(fs::exists(dir.file("o.png")));
        // Every frame of an animation is asked: the first lost, none written.
        r = runGlimmer({"render", script, "-o", dir.file("f%03d.png"), "--frames", "3", "--size", "16x16",
                        "--backend", "osmesa"});
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_FALSE(fs::exists(dir.file("f000.png")));
    }
    {
        // A watch's values and summary are read the same way: no summary, no file.
        TestFaultEnv fault("reset:scripts/bloom.glib:");
        auto w = runGlimmer({"-q", "render", "scripts/bloom.glib", "--backend", "osmesa", "--size", "16x16", "--watch",
                             "bloom.frag:12:rgbblur", "-o", dir.file("w.pfm")});
        EXPECT_EQ(w.exitCode, 1) << w.err;
        EXPECT_EQ(w.out, "");
        EXPECT_EQ(w.err, "glimmer: error: the GPU was reset by another process while this script drew "
                         "(GLIMMER_TEST_FAULT)\n");
        EXPECT_FALSE(fs::exists(dir.file("w.pfm")));
    }
    // The same command with no fault: the picture, so the fault was the cause.
    auto r = runGlimmer(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir.file("o.png")));
}

}  // namespace
