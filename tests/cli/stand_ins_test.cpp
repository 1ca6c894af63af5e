// --stand-ins: a script whose images, cube-map faces, 3-D .tex and OBJ are
// missing renders with a warning on each line that names one; without the
// flag render still exits 1, and a missing shader stays an error.
#include <gtest/gtest.h>

#include "cli/run_glimmer.h"
#include "image/image.h"

namespace glimmer_cli {
namespace {

std::array<int, 3> px(const glimmer::Image& img, int x, int y) {
    const std::uint8_t* p = &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
    return {p[0], p[1], p[2]};
}

TEST(CliStandIns, WithoutTheFlagAMissingFileIsAnError) {
    TempDir dir;
    auto r = runGlimmer({"render", cliData("stand_ins.glib"), "-o", dir.file("o.png"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(countOf(r.err, ": error: cannot find "), 4) << r.err;  // a cube map stops at its first
}

TEST(CliStandIns, RenderDrawsACheckerboardAndASphere) {
    TempDir dir;
    auto r = runGlimmer({"-v", "render", cliData("stand_ins.glib"), "-o", dir.file("o.png"), "--size", "128x128",
                         "--backend", "osmesa", "--stand-ins"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // One warning per missing file, on the script's line and column.
    EXPECT_EQ(countOf(r.err, ": warning: cannot find "), 9) << r.err;
    EXPECT_EQ(countOf(r.err, "; a stand-in takes its place (--stand-ins)\n"), 8) << r.err;
    // The model's says what stands in: a sphere sized to the view (Ortho -2 2,
    // Scale .5: a radius of 1.6 spans 40% of the height).
    EXPECT_EQ(countOf(r.err, "; a sphere of radius 1.6 stands in for it, 40% of the view's height (--stand-ins)\n"), 1)
        << r.err;
    EXPECT_NE(r.err.find(cliData("stand_ins.glib") + ":4:13: warning: cannot find texture 'lost_picture.bmp'"),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find(cliData("stand_ins.glib") + ":17:5: warning: cannot find model 'lost_model.obj'"),
              std::string::npos) << r.err;
    glimmer::Image img;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("o.png"), img, why)) << why;
    // The quad covers x 0..63, y 32..95 (Ortho -2 2 -2 2 at 128): the
    // checkerboard's 8 x 8 cells are 8 pixels, magenta at its top-left corner.
    const std::array<int, 3> magenta{255, 0, 255}, grey{128, 128, 128}, red{255, 0, 0}, black{0, 0, 0};
    EXPECT_EQ(px(img, 4, 36), magenta);
    EXPECT_EQ(px(img, 12, 36), grey);
    EXPECT_EQ(px(img, 12, 44), magenta);
    EXPECT_EQ(px(img, 60, 92), magenta);
    // The model: a sphere of radius 1.6 scaled by .5 at x = 1 (pixel 96): a
    // radius of 25.6 pixels, 40% of the 128-pixel height across.
    EXPECT_EQ(px(img, 96, 64), red);
    EXPECT_EQ(px(img, 96 + 24, 64), red);
    EXPECT_EQ(px(img, 96 + 28, 64), black);
    EXPECT_EQ(px(img, 96, 64 - 24), red);
    EXPECT_EQ(px(img, 96, 64 - 28), black);
}

// A scene set up for a 60-unit model, 150 units from the eye: the missing
// model's stand-in spans 40% of the view's height, centred where it sits.
TEST(CliStandIns, AMissingModelsStandInIsSizedToTheView) {
    TempDir dir;
    auto r = runGlimmer({"render", cliData("stand_in_dragon.glib"), "-o", dir.file("o.png"), "--size", "100x100",
                         "--backend", "osmesa", "--stand-ins"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find(cliData("stand_in_dragon.glib") + ":10:5: warning: cannot find model 'lost_dragon.obj'"),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find("); a sphere of radius 28 stands in for it, 40% of the view's height (--stand-ins)\n"),
              std::string::npos) << r.err;
    glimmer::Image img;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("o.png"), img, why)) << why;
    // Its outline, row 50 and column 50: red from about 30 to 70 (a little
    // wider: a perspective shows a sphere's silhouette slightly larger).
    int left = -1, right = -1, top = -1, bottom = -1;
    for (int i = 0; i < 100; ++i) {
        if (px(img, i, 50)[0] == 255) {
            if (left < 0) left = i;
            right = i;
        }
        if (px(img, 50, i)[0] == 255) {
            if (top < 0) top = i;
            bottom = i;
        }
    }
    EXPECT_NEAR(right - left + 1, 40, 3);
    EXPECT_NEAR(bottom - top + 1, 40, 3);
    EXPECT_NEAR((left + right) / 2.0, 49.5, 1.5);
}

TEST(CliStandIns, CheckLoadsEveryStandIn) {
    auto r = runGlimmer({"-v", "check", cliData("stand_ins.glib"), "--backend", "osmesa", "--stand-ins"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, ": warning: cannot find "), 9) << r.err;
    EXPECT_EQ(countOf(r.err, ": error:"), 0) << r.err;
}

TEST(CliStandIns, AMissingShaderStaysAnError) {
    auto r = runGlimmer({"check", cliData("stand_in_shader.glib"), "--backend", "osmesa", "--stand-ins"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(cliData("stand_in_shader.glib") + ":4:10: error: cannot find shader 'lost_shader.frag'"),
              std::string::npos) << r.err;
}

}  // namespace
}  // namespace glimmer_cli
