// What the passes that run use (plan/usage.h): only those files are read and
// those GL objects made; `check` takes every one.
#include <gtest/gtest.h>

#include "plan/usage.h"
#include "plan_test_util.h"

using namespace glimmer;
using namespace glimmer::test;

namespace {

// A pass into unit 6 that nobody reads is not needed: its target, its
// program and its mesh are not made for a render, and are for a check.
TEST(Usage, APassNobodyReadsUsesNothingUnlessEverythingIsAskedFor) {
    TempProject tp;
    Planned pl = plan(tp.script(), "Vertex a.vert\nFragment a.frag\n"
                                   "Texture2D 6 8 8\nRenderToTexture 6\nProgram Unread\nSphere 1 8 8\n"
                                   "RenderToTexture\nProgram Shown\nQuadXY 0 1\n");
    ASSERT_EQ(errors(pl.diags), std::vector<std::string>{});
    const Plan& p = pl.plan;
    ASSERT_EQ(p.passes.size(), 2u);
    ASSERT_FALSE(p.passes[0].needed);
    ASSERT_EQ(p.programs.size(), 2u);
    ASSERT_EQ(p.programs[0].name, "Unread");
    ASSERT_EQ(p.textures.size(), 1u);
    ASSERT_EQ(p.meshes.size(), 2u);
    ASSERT_EQ(p.meshes[0].shape, CommandKind::Sphere);
    Usage render = resourcesUsed(p, false);
    EXPECT_EQ(render.programs, (std::vector<bool>{false, true}));
    EXPECT_EQ(render.textures, (std::vector<bool>{false}));
    EXPECT_EQ(render.meshes, (std::vector<bool>{false, true}));
    Usage check = resourcesUsed(p, true);
    EXPECT_EQ(check.programs, (std::vector<bool>{true, true}));
    EXPECT_EQ(check.textures, (std::vector<bool>{true}));
    EXPECT_EQ(check.meshes, (std::vector<bool>{true, true}));
}

}  // namespace
