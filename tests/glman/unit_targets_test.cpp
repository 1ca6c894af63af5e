// A texture unit holds one texture per target, as in OpenGL (issue 19): a
// CubeMap and a Texture2D on one unit are both there for their samplers.
#include <gtest/gtest.h>

#include "glman_harness.h"

namespace glimmer::glmantest {
namespace {

TEST(UnitTargets, ACubeMapAndA2DTextureOnOneUnitAreBothRead) {
    auto r = runPipeline(script("unit_targets"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning), std::vector<std::string>{}) << r->printed();
    // Left (Program Flat, sampler2D on unit 6): grid3.bmp, whose middle cell
    // is cyan, around the quad's centre. Right (Program Sky, samplerCube on
    // unit 6, drawn after the image was bound there): the +x face at its
    // centre, the dark red (73 20 20) of its pattern (as cubemap_axes reads it).
    const std::uint8_t* left = pixel(r->screen, 8, 16);
    const std::uint8_t* right = pixel(r->screen, 24, 16);
    EXPECT_LT(left[0], 60) << "the 2-D texture is not there";
    EXPECT_GT(left[1], 200);
    EXPECT_GT(left[2], 200);
    EXPECT_NEAR(right[0], 73, 2) << "the cube map is not there";
    EXPECT_NEAR(right[1], 20, 2);
    EXPECT_NEAR(right[2], 20, 2);
}

// One Program whose sampler2D and samplerCube share a unit: OpenGL refuses
// the draw (GL_INVALID_OPERATION), so it is said where the Program is.
TEST(UnitTargets, SamplersOfTwoKindsOnOneUnitInOneProgramAreWarnedAbout) {
    auto r = runPipeline(script("mixed_sampler_unit"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              std::vector<std::string>{"Program Both: sampler2D uTex and samplerCube uSky both read unit 6; OpenGL "
                                       "draws nothing with samplers of two kinds on one unit: give them different "
                                       "units"})
        << r->printed();
}

}  // namespace
}  // namespace glimmer::glmantest
