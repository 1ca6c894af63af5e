// Which passes a change re-runs: the seed bloom, and chains built to catch
// the cases where running too little would leave a stale picture.
#include <gtest/gtest.h>

#include "plan/dependencies.h"
#include "plan/uniform_values.h"
#include "plan_test_util.h"

#include <fstream>

using namespace glimmer;
using namespace glimmer::test;

namespace {

Plan seedBloom() {
    std::string file = std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib";
    std::ifstream f(file);
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    return plan(file, text).plan;
}

int programNamed(const Plan& p, const std::string& name) {
    for (size_t i = 0; i < p.programs.size(); ++i)
        if (p.programs[i].name == name) return int(i);
    return -1;
}

TEST(Dependencies, DraggingUAddRerunsOnlyTheComposite) {
    Plan p = seedBloom();
    ASSERT_EQ(p.passes.size(), 2u);
    Change c;
    c.programs = {programNamed(p, "Bloom")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{false, true}));
}

TEST(Dependencies, ChangingTheBlurRerunsTheBlurAndEverythingDownstream) {
    Plan p = seedBloom();
    Change c;
    c.programs = {programNamed(p, "SuperBlur")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, true}));
}

TEST(Dependencies, NoChangeRunsNothing) {
    Plan p = seedBloom();
    EXPECT_EQ(passesToRun(p, Change{}), (std::vector<bool>{false, false}));
}

TEST(Dependencies, EverythingRunsEveryNeededPass) {
    Plan p = seedBloom();
    Change c;
    c.everything = true;
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, true}));
}

TEST(Dependencies, AReloadedImageRerunsItsReaders) {
    Plan p = seedBloom();
    Change c;
    c.textures = {p.finalUnits.at(5)};  // grid.bmp, read by both passes
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, true}));
}

// Two passes draw into the same screen: when the second changes, the first
// must draw again too, or the second would draw over its own old picture.
TEST(Dependencies, AllPassesIntoOneTargetRunTogether) {
    TempProject tp;
    Planned pl = plan(tp.script(),
                      "Vertex a.vert\nFragment a.frag\nProgram A\nQuadXY 0 1\n"
                      "Texture2D 6 8 8\nRenderToTexture 6\nProgram B\nQuadXY 0 1\n"
                      "RenderToTexture\nProgram C Img 6\nQuadXY 0 1\n");
    const Plan& p = pl.plan;
    ASSERT_EQ(p.passes.size(), 3u) << messages(pl.diags).size();
    Change c;
    c.programs = {programNamed(p, "C")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, false, true}));
    // B's target feeds C on the screen, and the screen also holds A's quad.
    c.programs = {programNamed(p, "B")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, true, true}));
}

// The same with a texture: B draws into unit 6 over what A drew there, so
// when B changes, A draws again first, and C, which reads 6, after both.
TEST(Dependencies, AllPassesIntoOneTextureRunTogether) {
    TempProject tp;
    Planned pl = plan(tp.script(),
                      "Vertex a.vert\nFragment a.frag\nTexture2D 6 8 8\nRenderToTexture 6\nProgram A\nQuadXY 0 1\n"
                      "RenderToTexture 6\nProgram B\nQuadXY 0 .5\n"
                      "RenderToTexture\nProgram C Img 6\nQuadXY 0 1\n");
    const Plan& p = pl.plan;
    ASSERT_EQ(p.passes.size(), 3u) << messages(pl.diags).size();
    ASSERT_EQ(p.passes[0].targets, p.passes[1].targets);
    Change c;
    c.programs = {programNamed(p, "B")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, true, true}));
    c.programs = {programNamed(p, "A")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{true, true, true}));
    c.programs = {programNamed(p, "C")};
    EXPECT_EQ(passesToRun(p, c), (std::vector<bool>{false, false, true}));
}

}  // namespace

namespace {

// Slider values survive a reload for uniforms whose Program, name and form
// stay; a range value is clamped into a range that shrank.
TEST(CarryOver, KeepsValuesOfUnchangedUniforms) {
    TempProject tp;
    Planned a = plan(tp.script(), "Vertex a.vert\nFragment a.frag\n"
                                  "Program P  uA <0 1 10>  uB <0 1 10>  uC <true>  uD <0 5 10>\nQuadXY 0 1\n");
    Planned b = plan(tp.script(), "Vertex a.vert\nFragment a.frag\nProgram Q uZ <0 1 2>\n"
                                  "Program P  uA <0 1 10>  uB {1 0 0}  uC <false>  uD <0 5 6>\nQuadXY 0 1\n");
    UniformValues old(a.plan);
    old.set(0, "uA", {7});
    old.set(0, "uB", {8});
    old.set(0, "uC", {0});
    old.set(0, "uD", {9});
    UniformValues now(b.plan);
    now.carryOver(a.plan, old, b.plan);
    EXPECT_EQ(now.get(1, "uA"), std::vector<double>{7});           // same form: kept, P is now program 1
    EXPECT_EQ(now.get(1, "uB"), (std::vector<double>{1, 0, 0, 1})); // form changed: from the script
    EXPECT_EQ(now.get(1, "uC"), std::vector<double>{0});           // bool kept
    EXPECT_EQ(now.get(1, "uD"), std::vector<double>{6});           // clamped to the new max
    EXPECT_EQ(now.get(0, "uZ"), std::vector<double>{1});
}

// A form that changed keeps nothing, even where the old value would fit
// (a range's one number into a checkbox, a checkbox into a range).
TEST(CarryOver, AChangedFormStartsFromTheScript) {
    TempProject tp;
    Planned a = plan(tp.script(), "Vertex a.vert\nFragment a.frag\nProgram P uE <0 1 10> uF <true>\nQuadXY 0 1\n");
    Planned b = plan(tp.script(), "Vertex a.vert\nFragment a.frag\nProgram P uE <false> uF <0 4 10>\nQuadXY 0 1\n");
    UniformValues old(a.plan);
    old.set(0, "uE", {7});
    UniformValues now(b.plan);
    now.carryOver(a.plan, old, b.plan);
    EXPECT_EQ(now.get(0, "uE"), std::vector<double>{0});
    EXPECT_EQ(now.get(0, "uF"), std::vector<double>{4});
}

TEST(CarryOver, ProgramsDifferingFrom) {
    TempProject tp;
    Planned a = plan(tp.script(), "Vertex a.vert\nFragment a.frag\nProgram P uA <0 1 10>\nProgram Q uB <0 1 10>\n");
    UniformValues x(a.plan), y(a.plan);
    EXPECT_TRUE(x.programsDifferingFrom(y).empty());
    y.set(1, "uB", {3});
    EXPECT_EQ(x.programsDifferingFrom(y), std::set<int>{1});
    // A uniform that only one side holds (a reload added it) is a difference, either way round.
    Planned b = plan(tp.script(), "Vertex a.vert\nFragment a.frag\nProgram P uA <0 1 10> uC <true>\nProgram Q uB <0 1 10>\n");
    UniformValues z(b.plan);
    EXPECT_EQ(x.programsDifferingFrom(z), std::set<int>{0});
    EXPECT_EQ(z.programsDifferingFrom(x), std::set<int>{0});
}

}  // namespace
