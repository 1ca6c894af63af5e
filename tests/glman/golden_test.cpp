// Every classroom-style script of tests/data/glman rendered on OSMesa and
// compared with the picture stored in tests/data/glman/expected (made by
// Glimmer and checked by eye). At most one 8-bit step per channel may differ.
// GLIMMER_UPDATE_EXPECTED=1 writes the pictures instead (then look at them).
#include <cstdlib>

#include <gtest/gtest.h>

#include "glman_harness.h"

using namespace glimmer;
using namespace glimmer::glmantest;
using glimmer::testing::compareRgb;

namespace {

class Golden : public ::testing::TestWithParam<const char*> {};

TEST_P(Golden, MatchesTheStoredPicture) {
    const std::string name = GetParam();
    auto r = glimmer::testing::renderScript("osmesa", script(name), {}, {});
    ASSERT_TRUE(r.ok) << r.error;
    const std::string expected = dataDir() + "/expected/" + name + ".png";
    const char* update = std::getenv("GLIMMER_UPDATE_EXPECTED");
    if (update && *update && std::string(update) != "0") {
        std::string why;
        ASSERT_TRUE(writePng(expected, r.screen, why)) << why;
        GTEST_SKIP() << "wrote " << expected;
    }
    Image want;
    std::string why;
    ASSERT_TRUE(loadImage(expected, want, why)) << why;
    ASSERT_EQ(want.width, r.screen.width);
    ASSERT_EQ(want.height, r.screen.height);
    auto d = compareRgb(r.screen, want);
    EXPECT_LE(d.maxSteps, 1) << name << ": " << d.maxSteps << " steps at (" << d.x << ", " << d.y << "), "
                             << d.pixelsOver1 << " pixels differ by more than 1";
}

INSTANTIATE_TEST_SUITE_P(Glman, Golden,
                         ::testing::Values("quad_texture", "sphere_ortho", "teapot", "cone_cylinder_disk",
                                           "wire_shapes", "objadj", "triangles_linesadj", "glbegin",
                                           "tessellation", "clouds", "quadbox", "skybox", "cubemap_axes",
                                           "texture3d", "noise", "noise2_stats", "flat_smooth", "uniform_forms",
                                           "all_commands"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
