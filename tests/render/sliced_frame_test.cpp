// A frame drawn in bands (Renderer::renderSlice, what the viewer uses so a
// heavy pass never freezes it) must end with exactly the bytes of one
// render() call: every target and the screen, on flat post-processes and
// on a perspective scene with depth.
#include <limits>

#include <gtest/gtest.h>

#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

struct Prepared {
    std::unique_ptr<GlContext> context;
    std::unique_ptr<Renderer> renderer;
    LoadedScript loaded;
    std::string error;
};

// The script on its own context and renderer, targets kept for reading.
std::unique_ptr<Prepared> prepare(const std::string& script, int size) {
    auto p = std::make_unique<Prepared>();
    Diagnostics diags;
    PlanOptions options;
    options.width = options.height = size;
    options.keepTargets = {5, 6};
    options.includeDirs.push_back(std::string(GLIMMER_SOURCE_DIR) + "/shaders");
    if (!loadScript(script, options, diags, p->loaded) || diags.hasErrors()) {
        p->error = "script did not load";
        return p;
    }
    Rig rig = makeRig(testBackends().front(), p->loaded, diags);
    p->context = std::move(rig.context);
    p->renderer = std::move(rig.renderer);
    p->error = rig.error;
    return p;
}

std::vector<bool> allPasses(const Plan& plan) { return std::vector<bool>(plan.passes.size(), true); }

// Every target and the screen, read back as float (exact for RGBA8 too).
std::vector<Image> readAll(Renderer& r) {
    std::vector<Image> out{r.readScreen()};
    for (int t : r.renderTargets()) out.push_back(r.readTextureFloat(t));
    return out;
}

void expectIdentical(const std::vector<Image>& a, const std::vector<Image>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].width, b[i].width);
        EXPECT_TRUE(a[i].u8 == b[i].u8) << "image " << i << " (0 is the screen) differs in its bytes";
        EXPECT_TRUE(a[i].f32 == b[i].f32) << "image " << i << " (0 is the screen) differs in its floats";
    }
}

// Renders once whole and once in slices of `budgetMs` with other values in
// between (so a stale picture would show); returns how many slices it took.
int compareSlicedWithWhole(const std::string& script, int size, const std::vector<std::string>& sets,
                           double budgetMs) {
    auto p = prepare(script, size);
    if (!p->renderer) {
        ADD_FAILURE() << p->error;
        return 0;
    }
    const Plan& plan = p->loaded.plan;
    UniformValues values(plan);
    Diagnostics diags;
    for (const auto& s : sets) EXPECT_TRUE(values.applySet(plan, s, diags)) << s;
    p->renderer->render(values, 0.0);
    const std::vector<Image> whole = readAll(*p->renderer);

    UniformValues other(plan);  // the script's defaults: a different picture
    p->renderer->render(other, 0.0);
    SlicedFrame frame = p->renderer->startFrame(values, 0.0, allPasses(plan));
    int slices = 0;
    double lastProgress = 0;
    while (!p->renderer->renderSlice(frame, budgetMs)) {
        ++slices;
        double now = p->renderer->progress(frame);
        EXPECT_GE(now, lastProgress);
        EXPECT_LT(now, 1.0);
        lastProgress = now;
        if (slices > 100000) {
            ADD_FAILURE() << "the sliced frame never finished";
            return slices;
        }
    }
    EXPECT_EQ(p->renderer->progress(frame), 1.0);
    expectIdentical(readAll(*p->renderer), whole);
    return slices + 1;
}

TEST(SlicedFrame, SeedBloomInBandsIsBitIdenticalToOneRender) {
    // A 23x23 superblur into a 512x512 target, then the composite at
    // 128x128. Budget 0 makes the bands the same on any machine: each pass's
    // first a sixteenth of its rows (no rate measured yet), then one row per
    // slice: 1 + 480 bands for the blur, 1 + 120 for the composite.
    int slices = compareSlicedWithWhole(std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib", 128,
                                        {"uHalfSize=11", "uAdd=2"}, 0.0);
    EXPECT_EQ(slices, 481 + 121);
}

TEST(SlicedFrame, PerspectiveSceneWithDepthInOneRowBandsIsBitIdentical) {
    // Budget 0: after its first band each pass draws one row per slice, so
    // every band clears and tests depth on its own rows.
    int slices = compareSlicedWithWhole(std::string(GLIMMER_SOURCE_DIR) + "/scripts/shapes.glib", 48,
                                        {"uStripes=3"}, 0.0);
    EXPECT_EQ(slices, 1 + 45);  // one pass of 48 rows: 3, then 45 of one
}

TEST(SlicedFrame, AnInfiniteBudgetDrawsTheFrameInOneSlice) {
    auto p = prepare(std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib", 64);
    ASSERT_TRUE(p->renderer) << p->error;
    UniformValues values(p->loaded.plan);
    SlicedFrame frame = p->renderer->startFrame(values, 0.0, allPasses(p->loaded.plan));
    EXPECT_TRUE(p->renderer->renderSlice(frame, std::numeric_limits<double>::infinity()));
    int drawn = 0;
    for (const Pass& pass : p->loaded.plan.passes) drawn += pass.needed;
    EXPECT_EQ(frame.timings.size(), size_t(drawn));
}

// A frame given up part-way (the slider moved again) hands its unfinished
// passes to the next one: the pass under way and every later one it drew.
TEST(SlicedFrame, UnfinishedListsThePassUnderWayAndTheRest) {
    auto p = prepare(std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib", 64);
    ASSERT_TRUE(p->renderer) << p->error;
    const Plan& plan = p->loaded.plan;
    UniformValues values(plan);
    ASSERT_TRUE(values.applySet(plan, "uHalfSize=11", *std::make_unique<Diagnostics>()));
    SlicedFrame frame = p->renderer->startFrame(values, 0.0, allPasses(plan));
    EXPECT_EQ(frame.unfinished(), allPasses(plan));
    ASSERT_FALSE(p->renderer->renderSlice(frame, 0.0));  // one band: a sixteenth of the blur
    std::vector<bool> left = frame.unfinished();
    ASSERT_LT(frame.pass, plan.passes.size());
    for (size_t i = 0; i < left.size(); ++i) EXPECT_EQ(left[i], i >= frame.pass) << "pass " << i;
    while (!p->renderer->renderSlice(frame, 1e9)) {
    }
    EXPECT_EQ(frame.unfinished(), std::vector<bool>(plan.passes.size(), false));
}

}  // namespace
