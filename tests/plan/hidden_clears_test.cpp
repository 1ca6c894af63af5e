// A Clear that a later draw of its pass paints over everywhere is marked,
// and only then: the quad must reach every corner of the viewport, in front
// of the eye and inside the depth range; other shapes are never assumed to.
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "plan/hidden_clears.h"
#include "plan_test_util.h"

using namespace glimmer;
using namespace glimmer::test;

namespace {

MeshDecl quad(CommandKind shape, double offset, double size) {
    MeshDecl m;
    m.shape = shape;
    m.params = {offset, size, 1, 1};
    return m;
}

TEST(HiddenClears, AQuadAsLargeAsTheOrthoViewCoversIt) {
    const glm::mat4 ortho = glm::ortho(-3.f, 3.f, -3.f, 3.f, -10.f, 10.f);
    EXPECT_TRUE(coversViewport(quad(CommandKind::QuadXY, .2, 5), ortho));
    EXPECT_TRUE(coversViewport(quad(CommandKind::QuadXY, .2, 3.001), ortho));
    EXPECT_FALSE(coversViewport(quad(CommandKind::QuadXY, .2, 2.9), ortho));
    // Moved right by 1: its left edge is inside the view.
    EXPECT_FALSE(coversViewport(quad(CommandKind::QuadXY, .2, 3.5), ortho * glm::translate(glm::mat4(1), {1, 0, 0})));
    // Cut by the far plane.
    EXPECT_FALSE(coversViewport(quad(CommandKind::QuadXY, -20, 5), ortho));
}

TEST(HiddenClears, EdgeOnAndBehindTheEyeDoNotCover) {
    const glm::mat4 ortho = glm::ortho(-3.f, 3.f, -3.f, 3.f, -10.f, 10.f);
    EXPECT_FALSE(coversViewport(quad(CommandKind::QuadXZ, 0, 50), ortho));  // seen edge-on: a line
    EXPECT_TRUE(coversViewport(quad(CommandKind::QuadXZ, 0, 5), ortho * glm::rotate(glm::mat4(1), 1.5707964f, {1, 0, 0})));
    const glm::mat4 eye = glm::perspective(glm::radians(50.f), 1.f, .1f, 100.f) *
                          glm::lookAt(glm::vec3(0, 0, 8), glm::vec3(0), glm::vec3(0, 1, 0));
    EXPECT_TRUE(coversViewport(quad(CommandKind::QuadXY, 0, 10), eye));
    EXPECT_FALSE(coversViewport(quad(CommandKind::QuadXY, 9, 100), eye));  // behind the eye
}

TEST(HiddenClears, OtherShapesNeverCount) {
    MeshDecl sphere;
    sphere.shape = CommandKind::Sphere;
    sphere.params = {100, 32, 32};
    EXPECT_FALSE(coversViewport(sphere, glm::mat4(1)));
}

// The seed bloom's screen pass: Clear, then QuadXY .2 5. under the default
// Ortho: the Clear is hidden by the quad (step 1). A pass whose quad leaves
// a border keeps its Clear, and so does one that draws depth.
TEST(HiddenClears, MarkedInThePlanOnlyWhereTheQuadCoversTheTarget) {
    TempProject p;
    auto r = plan(p.script(),
                  "Vertex a.vert\nFragment a.frag\nProgram A\n"
                  "Texture2D 6 64 64\nRenderToTexture 6\nClear\nQuadXY .2 2.\nRenderToTexture\n"
                  "Texture2D 7 64 64\nRenderToTexture 7\nClear\nQuadXY .2 5.\nSphere 1\nRenderToTexture\n"
                  "Clear\nQuadXY .2 5.\n");
    ASSERT_TRUE(r.diags.all().empty() || !r.diags.hasErrors());
    ASSERT_EQ(r.plan.passes.size(), 3u);
    const auto& small = r.plan.passes[0].steps;
    ASSERT_EQ(small[0].kind, Step::Kind::Clear);
    EXPECT_EQ(small[0].hiddenBy, -1);
    const auto& deep = r.plan.passes[1].steps;
    EXPECT_TRUE(r.plan.passes[1].needsDepth);
    EXPECT_EQ(deep[0].hiddenBy, -1);
    const auto& screen = r.plan.passes[2].steps;
    ASSERT_EQ(screen[0].kind, Step::Kind::Clear);
    EXPECT_EQ(screen[0].hiddenBy, 1);
}

}  // namespace
