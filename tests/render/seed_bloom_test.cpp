// The seed's bloom.glib, exactly as on the slides. Its blur pass draws
// QuadXY .2 3. under glman's default Ortho -3 3 -3 3 (the seed's own Ortho is
// degenerate and OpenGL keeps the default) into a 512x512 target from a
// 512x512 image: the quad covers the target exactly, so the seed itself is a
// calibration scene for the superblur.
#include <gtest/gtest.h>

#include "bloom/superblur_reference.h"
#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

class SeedBloom : public ::testing::TestWithParam<int> {};

TEST_P(SeedBloom, BlurPassMatchesReference) {
    const int half = GetParam();
    PlanOptions options;
    options.width = options.height = 512;
    Rendered r = renderScript(testBackends().front(), std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib",
                              {"uHalfSize=" + std::to_string(half), "uAdd=2"}, {5, 6}, options);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.units[5].width, 512);
    ASSERT_EQ(r.units[6].width, 512);
    Image expected = quantizeToRgba8(superblurReference(toRgb(r.units[5]), half));
    Difference d = compareRgb(r.units[6], expected);
    EXPECT_LE(d.maxSteps, 1) << "off by " << d.maxSteps << " at " << d.x << "," << d.y;
    EXPECT_EQ(r.screen.width, 512);
}

INSTANTIATE_TEST_SUITE_P(HalfSizes, SeedBloom, ::testing::Values(0, 1, 5, 11));

// The glow must sit on the lines it comes from: where the image has a
// bright grid line, the bloom is at least as bright as the image there.
TEST(SeedBloomPicture, GlowAddsToTheImage) {
    PlanOptions options;
    options.width = options.height = 128;
    Rendered none = renderScript(testBackends().front(), std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib",
                                 {"uHalfSize=5", "uAdd=0"}, {}, options);
    Rendered glow = renderScript(testBackends().front(), std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib",
                                 {"uHalfSize=5", "uAdd=2"}, {}, options);
    ASSERT_TRUE(none.ok) << none.error;
    ASSERT_TRUE(glow.ok) << glow.error;
    long brighter = 0, darker = 0;
    for (size_t i = 0; i < none.screen.u8.size(); ++i) {
        if (i % 4 == 3) continue;
        brighter += glow.screen.u8[i] > none.screen.u8[i];
        darker += glow.screen.u8[i] < none.screen.u8[i];
    }
    EXPECT_EQ(darker, 0);
    EXPECT_GT(brighter, long(none.screen.u8.size() / 2));
}

}  // namespace
