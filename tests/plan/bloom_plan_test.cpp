// The seed bloom script, planned from its real file: two passes, a blur into
// texture 6 and a bloom onto the screen.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "plan/uniform_values.h"
#include "plan_test_util.h"

namespace glimmer::test {
namespace {

std::string readFile(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

class BloomPlan : public ::testing::Test {
protected:
    void SetUp() override {
        file = (fs::path(GLIMMER_SOURCE_DIR) / "scripts" / "bloom.glib").string();
        std::string text = readFile(file);
        ASSERT_FALSE(text.empty()) << file;
        p = plan(file, text);
    }
    std::string project(const std::string& rel) const {
        return (fs::path(GLIMMER_SOURCE_DIR) / rel).lexically_normal().string();
    }
    std::string file;
    Planned p;
};

TEST_F(BloomPlan, HasNoErrors) {
    EXPECT_FALSE(p.diags.hasErrors()) << ::testing::PrintToString(messages(p.diags));
    EXPECT_EQ(p.plan.scriptFile, file);
    EXPECT_EQ(p.plan.width, 600);
    EXPECT_EQ(p.plan.height, 600);
}

TEST_F(BloomPlan, DegenerateOrthoIsWarnedAboutExactly) {
    std::vector<std::string> expected = {
        "2:1: warning: degenerate Ortho -1. -1. 1. 1. (left == right): OpenGL rejects it and keeps the "
        "current projection, Ortho -3 3 -3 3"};
    std::vector<std::string> planWarnings;
    for (const auto& m : messages(p.diags))
        if (m.find("Ortho") != std::string::npos) planWarnings.push_back(m);
    EXPECT_EQ(planWarnings, expected);
    // The only other warnings are the parser's, about uniforms on lines of their own.
    for (const auto& w : warnings(p.diags)) {
        if (w.find("Ortho") == std::string::npos) {
            EXPECT_NE(w.find("is on a line of its own"), std::string::npos) << w;
        }
    }
    EXPECT_EQ(p.diags.warningCount(), 6);
}

TEST_F(BloomPlan, Textures) {
    ASSERT_EQ(p.plan.textures.size(), 2u);  // grid.bmp is shared by units 5 and 7
    const TextureDecl& grid = p.plan.textures[0];
    EXPECT_EQ(grid.source, TextureDecl::Source::File);
    EXPECT_EQ(grid.shown, "grid.bmp");
    EXPECT_EQ(grid.path, project("textures/grid.bmp"));
    EXPECT_FALSE(grid.renderTarget);
    const TextureDecl& target = p.plan.textures[1];
    EXPECT_EQ(target.source, TextureDecl::Source::Empty);
    EXPECT_EQ(target.width, 512);
    EXPECT_EQ(target.height, 512);
    EXPECT_EQ(target.loc.line, 6);
    EXPECT_TRUE(target.renderTarget);
    EXPECT_FALSE(target.needsDepth);
    EXPECT_EQ(p.plan.finalUnits, (std::map<int, int>{{5, 0}, {6, 1}, {7, 0}}));
}

TEST_F(BloomPlan, TwoPasses) {
    ASSERT_EQ(p.plan.passes.size(), 2u);
    const Pass& blur = p.plan.passes[0];
    EXPECT_EQ(blur.targets, std::vector<int>{1});
    EXPECT_EQ(blur.loc.line, 7);
    EXPECT_EQ(blur.reads, std::set<int>{0});  // grid.bmp through unit 5
    EXPECT_TRUE(blur.needed);
    EXPECT_FALSE(blur.needsDepth);

    const Pass& bloom = p.plan.passes[1];
    EXPECT_TRUE(bloom.targets.empty());
    EXPECT_EQ(bloom.loc.line, 18);
    EXPECT_EQ(bloom.reads, (std::set<int>{0, 1}));  // texture 6 and the unit 7 image
    EXPECT_TRUE(bloom.needed);
    EXPECT_FALSE(bloom.needsDepth);
    EXPECT_TRUE(p.plan.screenNeeded());
}

TEST_F(BloomPlan, StepsAndDraws) {
    ASSERT_EQ(p.plan.passes.size(), 2u);
    const Pass& blur = p.plan.passes[0];
    ASSERT_EQ(blur.steps.size(), 2u);
    EXPECT_EQ(blur.steps[0].kind, Step::Kind::Clear);
    EXPECT_EQ(blur.steps[0].clearColor, glm::vec4(0, 0.5f, 0, 1));
    ASSERT_EQ(blur.steps[1].kind, Step::Kind::Draw);
    const Draw& d0 = blur.steps[1].draw;
    EXPECT_EQ(d0.program, 0);
    EXPECT_EQ(d0.loc.line, 16);
    EXPECT_EQ(d0.units, (std::map<int, int>{{5, 0}, {6, 1}}));

    const Pass& bloom = p.plan.passes[1];
    ASSERT_EQ(bloom.steps.size(), 2u);
    EXPECT_EQ(bloom.steps[0].kind, Step::Kind::Clear);
    EXPECT_EQ(bloom.steps[0].clearColor, glm::vec4(0, 0, 0, 1));
    ASSERT_EQ(bloom.steps[1].kind, Step::Kind::Draw);
    const Draw& d1 = bloom.steps[1].draw;
    EXPECT_EQ(d1.program, 1);
    EXPECT_EQ(d1.loc.line, 31);
    EXPECT_EQ(d1.units, (std::map<int, int>{{5, 0}, {6, 1}, {7, 0}}));

    ASSERT_EQ(p.plan.meshes.size(), 2u);
    EXPECT_EQ(p.plan.meshes[d0.mesh].shape, CommandKind::QuadXY);
    EXPECT_EQ(p.plan.meshes[d0.mesh].params, (std::vector<double>{0.2, 3, 1, 1}));
    EXPECT_EQ(p.plan.meshes[d1.mesh].params, (std::vector<double>{0.2, 5, 1, 1}));
}

TEST_F(BloomPlan, ProjectionStaysGlmansDefaultOrtho) {
    ASSERT_EQ(p.plan.passes.size(), 2u);
    glm::mat4 expected = glm::ortho(-3.f, 3.f, -3.f, 3.f, -1000.f, 1000.f);
    // The blur pass draws into the 512x512 texture, the bloom pass onto the
    // 600x600 screen: both square, so nothing is widened.
    EXPECT_TRUE(matNear(draws(p.plan.passes[0]).at(0)->projection, expected));
    EXPECT_TRUE(matNear(draws(p.plan.passes[1]).at(0)->projection, expected));
    glm::mat4 view = glm::lookAt(glm::vec3(0, 0, .5f), glm::vec3(0), glm::vec3(0, 1, 0));
    EXPECT_TRUE(matNear(draws(p.plan.passes[0]).at(0)->modelView, view));
    EXPECT_TRUE(matNear(draws(p.plan.passes[1]).at(0)->modelView, view));
}

TEST_F(BloomPlan, Programs) {
    ASSERT_EQ(p.plan.programs.size(), 2u);
    const ProgramDecl& blur = p.plan.programs[0];
    EXPECT_EQ(blur.name, "SuperBlur");
    EXPECT_FALSE(blur.gstap);
    ASSERT_EQ(blur.stages.size(), 2u);
    EXPECT_EQ(blur.stages[0].kind, ShaderStage::Kind::Vertex);
    EXPECT_EQ(blur.stages[0].path, project("shaders/superblur.vert"));
    EXPECT_EQ(blur.stages[0].shown, "superblur.vert");
    EXPECT_EQ(blur.stages[1].kind, ShaderStage::Kind::Fragment);
    EXPECT_EQ(blur.stages[1].path, project("shaders/superblur.frag"));
    ASSERT_EQ(blur.uniforms.size(), 2u);
    EXPECT_EQ(blur.uniforms[0].name, "uHalfSize");
    EXPECT_EQ(blur.uniforms[0].form, UniformSetting::Form::Range);
    EXPECT_EQ(blur.uniforms[0].min, 0);
    EXPECT_EQ(blur.uniforms[0].values, std::vector<double>{0});
    EXPECT_EQ(blur.uniforms[0].max, 11);
    EXPECT_EQ(blur.uniforms[1].name, "ImageUnit");
    EXPECT_EQ(blur.uniforms[1].form, UniformSetting::Form::Constant);
    EXPECT_EQ(blur.uniforms[1].values, std::vector<double>{5});

    const ProgramDecl& bloom = p.plan.programs[1];
    EXPECT_EQ(bloom.name, "Bloom");
    ASSERT_EQ(bloom.stages.size(), 2u);
    EXPECT_EQ(bloom.stages[0].path, project("shaders/bloom.vert"));
    EXPECT_EQ(bloom.stages[1].path, project("shaders/bloom.frag"));
    ASSERT_EQ(bloom.uniforms.size(), 3u);
    EXPECT_EQ(bloom.uniforms[0].name, "BlurUnit");
    EXPECT_EQ(bloom.uniforms[0].form, UniformSetting::Form::Constant);
    EXPECT_EQ(bloom.uniforms[0].values, std::vector<double>{6});
    EXPECT_EQ(bloom.uniforms[1].name, "ImageUnit");
    EXPECT_EQ(bloom.uniforms[1].values, std::vector<double>{7});
    EXPECT_EQ(bloom.uniforms[2].name, "uAdd");
    EXPECT_EQ(bloom.uniforms[2].form, UniformSetting::Form::Range);
    EXPECT_EQ(bloom.uniforms[2].min, 0);
    EXPECT_EQ(bloom.uniforms[2].values, std::vector<double>{0});
    EXPECT_EQ(bloom.uniforms[2].max, 4);
}

TEST_F(BloomPlan, KeepTargetsNeverDropsAndNothingIsDroppedAnyway) {
    PlanOptions o;
    o.keepTargets = {6};
    Planned q = plan(file, readFile(file), o);
    ASSERT_EQ(q.plan.passes.size(), 2u);
    EXPECT_TRUE(q.plan.passes[0].needed);
    EXPECT_TRUE(q.plan.passes[1].needed);
}

TEST_F(BloomPlan, UniformValuesStartFromTheScript) {
    UniformValues v(p.plan);
    EXPECT_EQ(v.get(0, "uHalfSize"), std::vector<double>{0});
    EXPECT_EQ(v.get(0, "ImageUnit"), std::vector<double>{5});
    EXPECT_EQ(v.get(1, "ImageUnit"), std::vector<double>{7});
    EXPECT_EQ(v.get(1, "uAdd"), std::vector<double>{0});
    EXPECT_TRUE(v.get(1, "uHalfSize").empty());
    EXPECT_EQ(v.all().size(), 5u);
}

TEST(SuperBlurPlan, OnePassOnTheScreenWithScale) {
    std::string file = (fs::path(GLIMMER_SOURCE_DIR) / "scripts" / "superblur.glib").string();
    std::ifstream f(file);
    std::stringstream s;
    s << f.rdbuf();
    Planned p = plan(file, s.str());
    EXPECT_FALSE(p.diags.hasErrors()) << ::testing::PrintToString(messages(p.diags));
    ASSERT_EQ(p.plan.passes.size(), 1u);
    EXPECT_TRUE(p.plan.passes[0].targets.empty());
    EXPECT_EQ(p.plan.passes[0].reads, std::set<int>{0});
    auto d = draws(p.plan.passes[0]);
    ASSERT_EQ(d.size(), 1u);
    glm::mat4 view = glm::lookAt(glm::vec3(0, 0, .5f), glm::vec3(0), glm::vec3(0, 1, 0));
    EXPECT_TRUE(matNear(d[0]->modelView, view * glm::scale(glm::mat4(1), glm::vec3(.5f))));
    EXPECT_TRUE(matNear(d[0]->projection, glm::ortho(-3.f, 3.f, -3.f, 3.f, -1000.f, 1000.f)));
}

}  // namespace
}  // namespace glimmer::test
