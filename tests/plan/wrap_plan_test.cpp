// Wrap (a Glimmer extension): the wrap mode of the textures declared after it.
#include <gtest/gtest.h>

#include "plan_test_util.h"

namespace glimmer::test {
namespace {

using V = std::vector<std::string>;
using W = TextureDecl::Wrap;

class WrapPlan : public ::testing::Test {
protected:
    Planned run(const std::string& text) { return plan(dir.script(), text); }
    TempProject dir;
};

TEST_F(WrapPlan, TexturesRepeatUntilAWrapAndFollowTheLastOne) {
    Planned p = run("Texture2D 5 img.bmp\n"
                    "Wrap clamp\n"
                    "Texture2D 6 64 64\n"
                    "Texture3D 7 4 4 4\n"
                    "WRAP Mirror\n"
                    "Texture2D 8 w h RGBA16F\n"
                    "Wrap repeat\n"
                    "Texture2D 9 8 8\n");
    EXPECT_EQ(errors(p.diags), V{});
    ASSERT_EQ(p.plan.textures.size(), 5u);
    EXPECT_EQ(p.plan.textures[0].wrap, W::Repeat);
    EXPECT_EQ(p.plan.textures[1].wrap, W::Clamp);
    EXPECT_EQ(p.plan.textures[2].wrap, W::Clamp);
    EXPECT_EQ(p.plan.textures[3].wrap, W::Mirror);
    EXPECT_EQ(p.plan.textures[4].wrap, W::Repeat);
}

TEST_F(WrapPlan, OneFileTwoWrapsIsTwoTextures) {
    Planned p = run("Texture2D 5 img.bmp\nWrap clamp\nTexture2D 6 img.bmp\nTexture2D 7 img.bmp\n");
    EXPECT_EQ(errors(p.diags), V{});
    ASSERT_EQ(p.plan.textures.size(), 2u);
    EXPECT_EQ(p.plan.finalUnits.at(6), p.plan.finalUnits.at(7));
    EXPECT_NE(p.plan.finalUnits.at(5), p.plan.finalUnits.at(6));
}

TEST_F(WrapPlan, OpenGLsOwnNamesAreAccepted) {
    Planned p = run("Wrap GL_CLAMP_TO_EDGE\nTexture2D 6 8 8\nWrap mirrored_repeat\nTexture2D 7 8 8\n");
    EXPECT_EQ(errors(p.diags), V{});
    ASSERT_EQ(p.plan.textures.size(), 2u);
    EXPECT_EQ(p.plan.textures[0].wrap, W::Clamp);
    EXPECT_EQ(p.plan.textures[1].wrap, W::Mirror);
}

TEST_F(WrapPlan, AnythingElseIsAnErrorAndKeepsTheWrapInForce) {
    Planned p = run("Wrap clamp\nWrap border\nWrap\nWrap clamp repeat\nWrap 1\nTexture2D 6 8 8\n");
    EXPECT_EQ(messages(p.diags),
              (V{"2:6: error: Wrap takes one of repeat, clamp or mirror, not 'border'",
                 "3:1: error: Wrap takes one of repeat, clamp or mirror",
                 "4:1: error: Wrap takes one of repeat, clamp or mirror",
                 "5:6: error: Wrap takes one of repeat, clamp or mirror, not '1'"}));
    ASSERT_EQ(p.plan.textures.size(), 1u);
    EXPECT_EQ(p.plan.textures[0].wrap, W::Clamp);
}

}  // namespace
}  // namespace glimmer::test
