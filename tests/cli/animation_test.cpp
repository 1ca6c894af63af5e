// render --frames N --fps F: the Timer uniform advances 1/F seconds a frame
// (glman's sawtooth over the script's Timer period, docs/glib.md); frames go
// to numbered PNGs or to one animated WebP that libwebp decodes back to the
// same pixels at the same times.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"
#include "image/animation.h"
#include "image/image.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

// timer.glib: red is Timer, period 2 s.
int expectedRed(double seconds) {
    double t = std::fmod(seconds / 2.0, 1.0);
    return int(std::lround(t * 255.0));
}

TEST(CliAnimation, NumberedFramesFollowTheTimer) {
    TempDir dir;
    auto r = runGlimmer({"render", cliData("timer.glib"), "--size", "8x8", "--frames", "5", "--fps", "4", "--time",
                         "1", "--backend", "osmesa", "-o", dir.file("frame_%04d.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "wrote 5 frames, " + dir.file("frame_0000.png") + " to " + dir.file("frame_0004.png") +
                                 " (8x8, 4 fps)\n"),
              1)
        << r.err;
    for (int i = 0; i < 5; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", i);
        glimmer::Image img;
        std::string why;
        ASSERT_TRUE(glimmer::loadImage(dir.file(name), img, why)) << why;
        // 1 s + i/4 s: Timer 0.5, 0.625, 0.75, 0.875, then 0 again (the period wraps).
        EXPECT_NEAR(img.u8[0], expectedRed(1.0 + i / 4.0), 1) << "frame " << i;
    }
    EXPECT_FALSE(fs::exists(dir.file("frame_0005.png")));
}

TEST(CliAnimation, AnimatedWebpDecodesToTheFramesAtTheirTimes) {
    TempDir dir;
    std::vector<std::string> args{"render", cliData("timer.glib"), "--size", "6x4", "--frames", "8", "--fps", "4",
                                  "--backend", "osmesa"};
    auto webp = args, pngs = args;
    webp.insert(webp.end(), {"-o", dir.file("clock.webp")});
    pngs.insert(pngs.end(), {"-o", dir.file("f%d.png")});
    auto r = runGlimmer(webp);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "wrote " + dir.file("clock.webp") + " (8 frames, 6x4, 4 fps)\n"), 1) << r.err;
    ASSERT_EQ(runGlimmer(pngs).exitCode, 0);
    glimmer::DecodedAnimation anim;
    std::string why;
    ASSERT_TRUE(glimmer::readAnimatedWebp(dir.file("clock.webp"), anim, why)) << why;
    EXPECT_EQ(anim.width, 6);
    EXPECT_EQ(anim.height, 4);
    EXPECT_EQ(anim.loopCount, 0);  // forever
    ASSERT_EQ(anim.frames.size(), 8u);
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(anim.timestampsMs[size_t(i)], (i + 1) * 250) << "frame " << i;
        glimmer::Image png;
        ASSERT_TRUE(glimmer::loadImage(dir.file("f" + std::to_string(i) + ".png"), png, why)) << why;
        EXPECT_EQ(anim.frames[size_t(i)].u8, png.u8) << "frame " << i << " is not what render drew";
        EXPECT_NEAR(png.u8[0], expectedRed(i / 4.0), 1) << "frame " << i;
        if (i > 0) {
            EXPECT_NE(anim.frames[size_t(i)].u8, anim.frames[size_t(i - 1)].u8) << "frame " << i;
        }
    }
}

TEST(CliAnimation, FramesNeedSomewhereToGo) {
    TempDir dir;
    auto r = runGlimmer({"render", cliData("timer.glib"), "--frames", "3", "--backend", "osmesa", "-o",
                         dir.file("x.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "glimmer: error: --frames 3 writes several pictures: give -o a frame pattern such as "
                     "frame_%04d.png, or an animated .webp\n");
    auto dash = runGlimmer({"render", cliData("timer.glib"), "--frames", "2", "-o", "-"});
    EXPECT_EQ(dash.exitCode, 2);
    auto bad = runGlimmer({"render", cliData("timer.glib"), "--frames", "2", "-o", dir.file("f%s.png")});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(bad.err, "glimmer: error: -o '" + dir.file("f%s.png") +
                           "': a frame name takes one %d, or %04d for a zero-padded number\n");
    auto zero = runGlimmer({"render", cliData("timer.glib"), "--frames", "0", "-o", dir.file("f%d.png")});
    EXPECT_EQ(zero.exitCode, 2);
    EXPECT_EQ(zero.err, "glimmer: error: --frames 0 --fps 24: --frames must be 1 or more and --fps more than 0\n");
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(FrameNames, PatternsAndTheirMistakes) {
    std::string out, why;
    EXPECT_TRUE(glimmer::frameFileName("frame_%04d.png", 7, out, why));
    EXPECT_EQ(out, "frame_0007.png");
    EXPECT_TRUE(glimmer::frameFileName("100%%_%d.png", 12, out, why));
    EXPECT_EQ(out, "100%_12.png");
    EXPECT_TRUE(glimmer::frameFileName("f%02d.png", 123, out, why));
    EXPECT_EQ(out, "f123.png");
    EXPECT_FALSE(glimmer::frameFileName("f%d_%d.png", 1, out, why));
    EXPECT_FALSE(glimmer::frameFileName("plain.png", 1, out, why));
    EXPECT_EQ(why, "'plain.png': a frame name takes exactly one %d (such as frame_%04d.png)");
    EXPECT_TRUE(glimmer::isFramePattern("a%04d.png"));
    EXPECT_FALSE(glimmer::isFramePattern("a%%.png"));
}

}  // namespace
}  // namespace glimmer_cli
