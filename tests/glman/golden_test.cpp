// Every classroom-style script of tests/data/glman rendered on OSMesa and
// compared with the picture stored in tests/data/glman/expected (made by
// Glimmer and checked by eye). At most one 8-bit step per channel may differ.
// A test run never writes the pictures: tools/update-golden.sh does, as a
// command of its own (issue 26: GLIMMER_UPDATE_EXPECTED used to turn these
// tests into skips that rewrote the pictures, so a run could pass having
// compared nothing).
#include <cstdlib>

#include <gtest/gtest.h>

#include "glman_harness.h"
#include "golden_scripts.h"

using namespace glimmer;
using namespace glimmer::glmantest;
using glimmer::testing::compareRgb;

namespace {

class Golden : public ::testing::TestWithParam<const char*> {};

TEST_P(Golden, MatchesTheStoredPicture) {
    const char* update = std::getenv("GLIMMER_UPDATE_EXPECTED");
    ASSERT_FALSE(update && *update)
        << "GLIMMER_UPDATE_EXPECTED is set, but a test run never rewrites the stored pictures (it would pass "
           "having compared nothing): run tools/update-golden.sh BUILD_DIR [NAME...] to rewrite them, look at "
           "each, and run the tests without it";
    const std::string name = GetParam();
    auto r = glimmer::testing::renderScript("osmesa", script(name), {}, {});
    ASSERT_TRUE(r.ok) << r.error;
    const std::string expected = dataDir() + "/expected/" + name + ".png";
    Image want;
    std::string why;
    ASSERT_TRUE(loadImage(expected, want, why)) << why;
    ASSERT_EQ(want.width, r.screen.width);
    ASSERT_EQ(want.height, r.screen.height);
    auto d = compareRgb(r.screen, want);
    EXPECT_LE(d.maxSteps, 1) << name << ": " << d.maxSteps << " steps at (" << d.x << ", " << d.y << "), "
                             << d.pixelsOver1 << " pixels differ by more than 1";
}

INSTANTIATE_TEST_SUITE_P(Glman, Golden, ::testing::ValuesIn(kGoldenScripts),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
