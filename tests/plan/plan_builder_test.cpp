// buildPlan on small scripts in a throw-away project folder: passes, what is
// needed, depth, matrices, sizes, textures, and the problems it reports.
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "plan_test_util.h"

namespace glimmer::test {
namespace {

using V = std::vector<std::string>;

class PlanTest : public ::testing::Test {
protected:
    Planned run(const std::string& text, const PlanOptions& o = {}) { return plan(dir.script(), text, o); }
    // The directories resolveFile reports, joined as in "looked in ...".
    std::string lookedIn() const {
        return dir.path("scripts") + ", " + dir.path("shaders") + ", " + dir.path("textures");
    }
    TempProject dir;
};

// A shader program sampling unit 5 (a bare number is how samplers get units).
const std::string kSampling5 = "Vertex a.vert\nFragment a.frag\nProgram P Tex 5\n";

// ---- which passes are needed -------------------------------------------

const std::string kUnreadTarget =
    "Texture2D 6 64 64\n"
    "RenderToTexture 6\n"
    "Clear\n"
    "QuadXY 0 1\n"
    "RenderToTexture\n"
    "Clear\n"
    "QuadXY 0 1\n";

TEST_F(PlanTest, PassNobodyReadsIsNotNeeded) {
    Planned p = run(kUnreadTarget);
    EXPECT_EQ(errors(p.diags), V{});
    ASSERT_EQ(p.plan.passes.size(), 2u);
    EXPECT_EQ(p.plan.passes[0].targets, std::vector<int>{0});
    EXPECT_FALSE(p.plan.passes[0].needed);
    EXPECT_TRUE(p.plan.passes[1].needed);
    EXPECT_TRUE(p.plan.passes[1].reads.empty());  // fixed function samples nothing
    EXPECT_TRUE(p.plan.textures[0].renderTarget);
}

TEST_F(PlanTest, KeepTargetsKeepsAnUnreadPass) {
    PlanOptions o;
    o.keepTargets = {6};
    Planned p = run(kUnreadTarget, o);
    ASSERT_EQ(p.plan.passes.size(), 2u);
    EXPECT_TRUE(p.plan.passes[0].needed);

    o.keepTargets = {5};  // nothing on unit 5: keeps nothing
    Planned q = run(kUnreadTarget, o);
    ASSERT_EQ(q.plan.passes.size(), 2u);
    EXPECT_FALSE(q.plan.passes[0].needed);
}

TEST_F(PlanTest, NeededFollowsReadsBackThroughAChain) {
    // A writes 6; B reads 6 (as unit 5) and writes 7; the screen reads 7 or not.
    std::string base =
        "Texture2D 6 64 64\nTexture2D 7 64 64\n"
        "RenderToTexture 6\nQuadXY 0 1\n"
        "RenderToTexture 7\n"
        "Vertex a.vert\nFragment a.frag\nProgram A Tex 6\nQuadXY 0 1\n"
        "RenderToTexture\n"
        "Program B Tex ";
    Planned reads7 = run(base + "7\nQuadXY 0 1\n");
    EXPECT_EQ(errors(reads7.diags), V{});
    ASSERT_EQ(reads7.plan.passes.size(), 3u);
    EXPECT_EQ(reads7.plan.passes[1].reads, std::set<int>{0});
    EXPECT_EQ(reads7.plan.passes[2].reads, std::set<int>{1});
    EXPECT_TRUE(reads7.plan.passes[0].needed);
    EXPECT_TRUE(reads7.plan.passes[1].needed);
    EXPECT_TRUE(reads7.plan.passes[2].needed);

    Planned reads9 = run(base + "9\nQuadXY 0 1\n");  // unit 9 is empty
    ASSERT_EQ(reads9.plan.passes.size(), 3u);
    EXPECT_TRUE(reads9.plan.passes[2].reads.empty());
    EXPECT_FALSE(reads9.plan.passes[0].needed);
    EXPECT_FALSE(reads9.plan.passes[1].needed);
    EXPECT_TRUE(reads9.plan.passes[2].needed);
}

TEST_F(PlanTest, UnsetSamplerReadsUnitZero) {
    Planned p = run(
        "Texture2D 0 img.bmp\n"
        "Vertex a.vert\nFragment a.frag\nProgram P\n"
        "QuadXY 0 1\n");
    ASSERT_EQ(p.plan.passes.size(), 1u);
    EXPECT_EQ(p.plan.passes[0].reads, std::set<int>{0});
}

TEST_F(PlanTest, PassesThatDrawNothingAreDropped) {
    Planned p = run("Texture2D 6 64 64\nRenderToTexture 6\nRenderToTexture\nQuadXY 0 1\n");
    ASSERT_EQ(p.plan.passes.size(), 1u);
    EXPECT_TRUE(p.plan.passes[0].targets.empty());
    EXPECT_FALSE(p.plan.textures[0].renderTarget);
    EXPECT_TRUE(p.plan.screenNeeded());

    Planned q = run("Texture2D 6 64 64\nRenderToTexture 6\nQuadXY 0 1\n");
    ASSERT_EQ(q.plan.passes.size(), 1u);
    EXPECT_FALSE(q.plan.screenNeeded());
}

TEST_F(PlanTest, ReadingOwnTargetIsWarned) {
    Planned p = run("Texture2D 5 64 64\nRenderToTexture 5\n" + kSampling5 + "QuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{"2:1: warning: a pass reads the texture it renders into; the result is undefined"});
}

// ---- depth ----------------------------------------------------------------

TEST_F(PlanTest, DepthForASphere) {
    Planned p = run("Texture2D 6 64 64\nRenderToTexture 6\nSphere\nRenderToTexture\nSphere 2\n");
    ASSERT_EQ(p.plan.passes.size(), 2u);
    EXPECT_TRUE(p.plan.passes[0].needsDepth);
    EXPECT_TRUE(p.plan.textures[0].needsDepth);
    EXPECT_TRUE(p.plan.passes[1].needsDepth);
    ASSERT_EQ(p.plan.meshes.size(), 2u);
    EXPECT_EQ(p.plan.meshes[0].params, (std::vector<double>{1, 60, 60}));
    EXPECT_EQ(p.plan.meshes[1].params, (std::vector<double>{2, 60, 60}));
}

TEST_F(PlanTest, DepthForTwoQuadsNotOne) {
    Planned two = run("Texture2D 6 64 64\nRenderToTexture 6\nQuadXY 0 1\nQuadXZ 0 1\n");
    ASSERT_EQ(two.plan.passes.size(), 1u);
    EXPECT_TRUE(two.plan.passes[0].needsDepth);
    EXPECT_TRUE(two.plan.textures[0].needsDepth);

    Planned one = run("Texture2D 6 64 64\nRenderToTexture 6\nClear\nQuadYZ 0 1\n");
    ASSERT_EQ(one.plan.passes.size(), 1u);
    EXPECT_FALSE(one.plan.passes[0].needsDepth);
    EXPECT_FALSE(one.plan.textures[0].needsDepth);
}

TEST_F(PlanTest, SameShapeTwiceIsOneMeshTwoDraws) {
    Planned p = run("QuadXY 0 1\nQuadXY 0 1\nQuadXY 0 2\n");
    EXPECT_EQ(p.plan.meshes.size(), 2u);
    ASSERT_EQ(p.plan.passes.size(), 1u);
    auto d = draws(p.plan.passes[0]);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0]->mesh, d[1]->mesh);
    EXPECT_NE(d[0]->mesh, d[2]->mesh);
}

// ---- matrices ---------------------------------------------------------------

TEST_F(PlanTest, ModelViewFollowsTransformsAndTheStack) {
    Planned p = run(
        "LookAt 1 2 5  0 0 0  0 1 0\n"
        "Translate 1 2 3\n"
        "PushMatrix\n"
        "Rotate 30 0 0 1\n"
        "Scale 2\n"
        "QuadXY 0 1\n"
        "PopMatrix\n"
        "Scale 1 2 3\n"
        "QuadXY 0 1\n"
        "TransformBegin\n"
        "Translate 4 5\n"
        "Rotate 90 1 0 0\n"
        "QuadXY 0 1\n"
        "TransformEnd\n"
        "QuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.passes.size(), 1u);
    auto d = draws(p.plan.passes[0]);
    ASSERT_EQ(d.size(), 4u);

    glm::mat4 view = glm::lookAt(glm::vec3(1, 2, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    glm::mat4 t = glm::translate(glm::mat4(1), glm::vec3(1, 2, 3));
    glm::mat4 r = glm::rotate(glm::mat4(1), glm::radians(30.f), glm::vec3(0, 0, 1));
    glm::mat4 s2 = glm::scale(glm::mat4(1), glm::vec3(2));
    glm::mat4 s123 = glm::scale(glm::mat4(1), glm::vec3(1, 2, 3));
    glm::mat4 t45 = glm::translate(glm::mat4(1), glm::vec3(4, 5, 0));
    glm::mat4 rx = glm::rotate(glm::mat4(1), glm::radians(90.f), glm::vec3(1, 0, 0));

    EXPECT_TRUE(matNear(d[0]->modelView, view * t * r * s2));
    EXPECT_TRUE(matNear(d[1]->modelView, view * t * s123));
    EXPECT_TRUE(matNear(d[2]->modelView, view * t * s123 * t45 * rx));
    EXPECT_TRUE(matNear(d[3]->modelView, view * t * s123));
    // A point: the last transform listed applies first.
    glm::vec4 pt = d[0]->modelView * glm::vec4(1, 0, 0, 1);
    glm::vec4 byHand = view * glm::vec4(1 + 2 * std::cos(glm::radians(30.f)), 2 + 2 * std::sin(glm::radians(30.f)), 3, 1);
    EXPECT_NEAR(pt.x, byHand.x, 1e-4);
    EXPECT_NEAR(pt.y, byHand.y, 1e-4);
    EXPECT_NEAR(pt.z, byHand.z, 1e-4);
}

TEST_F(PlanTest, WithoutLookAtTheEyeIsAtTheOrigin) {
    Planned p = run("Translate 0 0 -4\nQuadXY 0 1\n");
    auto d = draws(p.plan.passes.at(0));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_TRUE(matNear(d[0]->modelView, glm::translate(glm::mat4(1), glm::vec3(0, 0, -4))));
}

TEST_F(PlanTest, ZeroAxisRotateIsWarnedAndIgnored) {
    Planned p = run("Rotate 30 0 0 0\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{"1:1: warning: Rotate about a zero axis does nothing"});
    EXPECT_TRUE(matNear(draws(p.plan.passes.at(0)).at(0)->modelView, glm::mat4(1)));
}

TEST_F(PlanTest, BadLookAtIsAnError) {
    Planned p = run("LookAt 0 0 0 0 0 0 0 1 0\nQuadXY 0 1\n");
    EXPECT_EQ(errors(p.diags), V{"LookAt needs an eye apart from the point looked at, and an up vector "
                                  "not along the line of sight"});
}

TEST_F(PlanTest, DefaultProjectionIsOrthoMinus3To3) {
    Planned p = run("QuadXY 0 1\n");
    EXPECT_TRUE(matNear(draws(p.plan.passes.at(0)).at(0)->projection,
                        glm::ortho(-3.f, 3.f, -3.f, 3.f, -1000.f, 1000.f)));
}

TEST_F(PlanTest, OrthoIsWidenedForA2To1Window) {
    Planned wide = run("WindowSize 1200 600\nQuadXY 0 1\nOrtho -1 1 -2 2\nQuadXY 0 1\nOrtho 0 2 0 1\nQuadXY 0 1\n");
    EXPECT_EQ(messages(wide.diags), V{});
    auto d = draws(wide.plan.passes.at(0));
    ASSERT_EQ(d.size(), 3u);
    EXPECT_TRUE(matNear(d[0]->projection, glm::ortho(-6.f, 6.f, -3.f, 3.f, -1000.f, 1000.f)));
    EXPECT_TRUE(matNear(d[1]->projection, glm::ortho(-2.f, 2.f, -2.f, 2.f, -1000.f, 1000.f)));
    EXPECT_TRUE(matNear(d[2]->projection, glm::ortho(-1.f, 3.f, 0.f, 1.f, -1000.f, 1000.f)));

    Planned tall = run("WindowSize 600 1200\nQuadXY 0 1\n");
    EXPECT_TRUE(matNear(draws(tall.plan.passes.at(0)).at(0)->projection,
                        glm::ortho(-3.f, 3.f, -6.f, 6.f, -1000.f, 1000.f)));
}

TEST_F(PlanTest, OnlyTheScreenIsWidened) {
    // A quad drawn to cover a texture target must cover it exactly, whatever
    // the texture's shape; the 2:1 screen is widened.
    Planned p = run("WindowSize 1200 600\nTexture2D 6 200 100\nRenderToTexture 6\nQuadXY 0 1\n"
                    "RenderToTexture\nQuadXY 0 1\n");
    ASSERT_EQ(p.plan.passes.size(), 2u);
    EXPECT_TRUE(matNear(draws(p.plan.passes[0]).at(0)->projection,
                        glm::ortho(-3.f, 3.f, -3.f, 3.f, -1000.f, 1000.f)));
    EXPECT_TRUE(matNear(draws(p.plan.passes[1]).at(0)->projection,
                        glm::ortho(-6.f, 6.f, -3.f, 3.f, -1000.f, 1000.f)));
}

TEST_F(PlanTest, Perspective) {
    Planned p = run("WindowSize 800 400\nPerspective 70\nQuadXY 0 1\nPersp\nQuadXY 0 1\nOrtho\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{});
    auto d = draws(p.plan.passes.at(0));
    ASSERT_EQ(d.size(), 3u);
    EXPECT_TRUE(matNear(d[0]->projection, glm::perspective(glm::radians(70.f), 2.f, 0.1f, 1000.f)));
    EXPECT_TRUE(matNear(d[1]->projection, glm::perspective(glm::radians(50.f), 2.f, 0.1f, 1000.f)));
    EXPECT_TRUE(matNear(d[2]->projection, glm::ortho(-6.f, 6.f, -3.f, 3.f, -1000.f, 1000.f)));

    Planned bad = run("Perspective 180\nQuadXY 0 1\n");
    EXPECT_EQ(messages(bad.diags), V{"1:1: error: Perspective's field of view must be between 0 and 180 degrees"});
}

TEST_F(PlanTest, DegenerateOrthoKeepsTheProjectionInForce) {
    Planned p = run("Perspective 60\nOrtho 0 0 0 0\nQuadXY 0 1\nOrtho 1 2 3 3\n");
    EXPECT_EQ(messages(p.diags),
              (V{"2:1: warning: degenerate Ortho 0 0 0 0 (left == right): OpenGL rejects it and keeps the "
                 "current projection, Perspective 60",
                 "4:1: warning: degenerate Ortho 1 2 3 3 (bottom == top): OpenGL rejects it and keeps the "
                 "current projection, Perspective 60"}));
    EXPECT_TRUE(matNear(draws(p.plan.passes.at(0)).at(0)->projection,
                        glm::perspective(glm::radians(60.f), 1.f, 0.1f, 1000.f)));
}

// ---- sizes ----------------------------------------------------------------

TEST_F(PlanTest, WindowSizeAndOptionsSize) {
    Planned none = run("QuadXY 0 1\n");
    EXPECT_EQ(none.plan.width, 600);
    EXPECT_EQ(none.plan.height, 600);

    Planned script = run("QuadXY 0 1\nWindowSize 800 400\nWindowSize 100 100\n");
    EXPECT_EQ(script.plan.width, 800);  // the first one, wherever it stands
    EXPECT_EQ(script.plan.height, 400);
    // The size is known before the first draw is planned.
    EXPECT_TRUE(matNear(draws(script.plan.passes.at(0)).at(0)->projection,
                        glm::ortho(-6.f, 6.f, -3.f, 3.f, -1000.f, 1000.f)));

    PlanOptions o;
    o.width = 300;
    o.height = 600;
    Planned opt = run("WindowSize 800 400\nQuadXY 0 1\n", o);
    EXPECT_EQ(opt.plan.width, 300);
    EXPECT_EQ(opt.plan.height, 600);
    EXPECT_TRUE(matNear(draws(opt.plan.passes.at(0)).at(0)->projection,
                        glm::ortho(-3.f, 3.f, -6.f, 6.f, -1000.f, 1000.f)));

    Planned bad = run("WindowSize 0 400\n");
    EXPECT_EQ(errors(bad.diags), V{"WindowSize must be between 1 and 16384 pixels each way"});
    EXPECT_EQ(bad.plan.width, 600);
    EXPECT_EQ(bad.plan.height, 600);
}

// ---- textures ---------------------------------------------------------------

TEST_F(PlanTest, SameFileSharesOneTexture) {
    Planned p = run(
        "Texture2D 1 img.bmp\n"
        "QuadXY 0 1\n"
        "Texture2D 2 img.bmp\n"
        "Texture2D 3 ../textures/img.bmp\n"
        "Texture2D 1 other.bmp\n"
        "Texture2D 4 32 32\n"
        "Texture2D 5 32 32\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.textures.size(), 4u);
    EXPECT_EQ(p.plan.textures[0].path, dir.path("textures/img.bmp"));
    EXPECT_EQ(p.plan.textures[0].shown, "img.bmp");
    EXPECT_EQ(p.plan.textures[1].path, dir.path("textures/other.bmp"));
    EXPECT_EQ(p.plan.textures[2].source, TextureDecl::Source::Empty);
    EXPECT_EQ(p.plan.textures[3].source, TextureDecl::Source::Empty);  // empty textures are never shared
    EXPECT_EQ(p.plan.finalUnits, (std::map<int, int>{{1, 1}, {2, 0}, {3, 0}, {4, 2}, {5, 3}}));
    // A draw sees the units as they were when it was written.
    EXPECT_EQ(draws(p.plan.passes.at(0)).at(0)->units, (std::map<int, int>{{1, 0}}));
}

TEST_F(PlanTest, TextureArgumentErrors) {
    // (The last line: a unit below 0, which issue 40's sampled mutants found untested.)
    Planned p = run("Texture2D 32 img.bmp\nTexture2D 1.5 img.bmp\nTexture2D 1 0 10\nTexture2D\nTexture2D 1 2\n"
                    "Texture2D -1 img.bmp\n");
    EXPECT_EQ(messages(p.diags),
              (V{"1:11: error: Texture2D needs a texture unit from 0 to 31, not '32'",
                 "2:11: error: Texture2D needs a texture unit from 0 to 31, not '1.5'",
                 "3:13: error: a texture's size must be between 1 and 16384 each way",
                 "4:1: error: Texture2D needs a unit and a file, or a unit, a width and a height",
                 "5:1: error: Texture2D needs a unit and a file, or a unit, a width and a height",
                 "6:11: error: Texture2D needs a texture unit from 0 to 31, not '-1'"}));
    EXPECT_TRUE(p.plan.textures.empty());
}

TEST_F(PlanTest, RenderIntoSeveralTexturesOfOneSize) {
    Planned p = run("Texture2D 6 64 32\nTexture2D 7 64 32\nRenderToTexture 6 7\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.passes.size(), 1u);
    EXPECT_EQ(p.plan.passes[0].targets, (std::vector<int>{0, 1}));
    EXPECT_EQ(p.plan.passes[0].loc.line, 3);
    EXPECT_TRUE(p.plan.textures[0].renderTarget);
    EXPECT_TRUE(p.plan.textures[1].renderTarget);
}

TEST_F(PlanTest, RenderToTextureErrors) {
    Planned noTex = run("RenderToTexture 4\nQuadXY 0 1\n");
    EXPECT_EQ(messages(noTex.diags),
              V{"1:17: error: no texture on unit 4 to render into; give it one first with Texture2D 4 width height"});
    // The draw goes where drawing was going before: the screen.
    ASSERT_EQ(noTex.plan.passes.size(), 1u);
    EXPECT_TRUE(noTex.plan.passes[0].targets.empty());

    Planned image = run("Texture2D 5 img.bmp\nRenderToTexture 5\n");
    EXPECT_EQ(messages(image.diags),
              V{"2:17: error: unit 5 holds the image 'img.bmp'; render into an empty texture made with "
                "Texture2D 5 width height"});

    // An image after an empty texture is still reported as an image, not as a
    // size mismatch (an image's size is not known while planning).
    Planned imageSecond = run("Texture2D 5 img.bmp\nTexture2D 6 64 64\nRenderToTexture 6 5\n");
    EXPECT_EQ(messages(imageSecond.diags),
              V{"3:19: error: unit 5 holds the image 'img.bmp'; render into an empty texture made with "
                "Texture2D 5 width height"});

    Planned sizes = run("Texture2D 6 64 64\nTexture2D 7 32 64\nRenderToTexture 6 7\nQuadXY 0 1\n");
    EXPECT_EQ(messages(sizes.diags), V{"3:19: error: all textures rendered into at once must have the same size"});
    ASSERT_EQ(sizes.plan.passes.size(), 1u);
    EXPECT_TRUE(sizes.plan.passes[0].targets.empty());

    Planned unit = run("RenderToTexture foo\n");
    EXPECT_EQ(messages(unit.diags), V{"1:17: error: RenderToTexture needs a texture unit from 0 to 31, not 'foo'"});
}

// ---- files ------------------------------------------------------------------

TEST_F(PlanTest, MissingFilesSayWhereTheyWereLookedFor) {
    Planned p = run("Texture2D 5 x.bmp\nVertex nope.vert\nObj m.obj\n");
    EXPECT_EQ(messages(p.diags),
              (V{"1:13: error: cannot find texture 'x.bmp' (looked in " + lookedIn() + ")",
                 "2:8: error: cannot find shader 'nope.vert' (looked in " + lookedIn() + ")",
                 "3:5: error: cannot find model 'm.obj' (looked in " + lookedIn() + ")"}));
    EXPECT_TRUE(p.plan.textures.empty());
    EXPECT_TRUE(p.plan.meshes.empty());
}

// One mistake, one message (issue 19): a shader named but not found is the
// error; the Program after it is not also said to have no shaders.
TEST_F(PlanTest, AMissingShaderIsOneMessageNotTwo) {
    Planned p = run("Vertex nope.vert\nFragment gone.frag\nProgram P\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags),
              (V{"1:8: error: cannot find shader 'nope.vert' (looked in " + lookedIn() + ")",
                 "2:10: error: cannot find shader 'gone.frag' (looked in " + lookedIn() + ")"}));
    // A Program with no shader named at all is still told so.
    Planned none = run("Vertex\nProgram Q\nQuadXY 0 1\n");
    EXPECT_EQ(messages(none.diags), V{"2:1: warning: Program Q has no shaders; set Vertex and Fragment first"});
}

TEST_F(PlanTest, IncludeDirsAreSearchedLast) {
    fs::path extra = dir.root() / "extra";
    dir.touch("extra/x.bmp");
    dir.touch("extra/img.bmp");
    PlanOptions o;
    o.includeDirs = {extra.string()};
    Planned p = run("Texture2D 5 x.bmp\nTexture2D 6 img.bmp\nTexture2D 7 y.bmp\n", o);
    ASSERT_EQ(p.plan.textures.size(), 2u);
    EXPECT_EQ(p.plan.textures[0].path, dir.path("extra/x.bmp"));
    EXPECT_EQ(p.plan.textures[1].path, dir.path("textures/img.bmp"));  // the project folder wins
    EXPECT_EQ(errors(p.diags),
              V{"cannot find texture 'y.bmp' (looked in " + lookedIn() + ", " + extra.string() + ")"});
}

TEST_F(PlanTest, ScriptFolderComesFirstAndAbsolutePathsWork) {
    dir.touch("scripts/img.bmp");
    std::string abs = dir.path("textures/other.bmp");
    Planned p = run("Texture2D 5 img.bmp\nTexture2D 6 " + abs + "\nObj model.obj\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.textures.size(), 2u);
    EXPECT_EQ(p.plan.textures[0].path, dir.path("scripts/img.bmp"));
    EXPECT_EQ(p.plan.textures[1].path, abs);
    ASSERT_EQ(p.plan.meshes.size(), 1u);
    EXPECT_EQ(p.plan.meshes[0].shape, CommandKind::Obj);
    EXPECT_EQ(p.plan.meshes[0].path, dir.path("scripts/model.obj"));
}

// ---- programs -----------------------------------------------------------------

TEST_F(PlanTest, ProgramsTakeTheCurrentShaders) {
    Planned p = run(
        "Vertex a.vert\nFragment a.frag\nProgram One\nQuadXY 0 1\n"
        "Fragment b.frag\nGSTAP\nProgram Two\nQuadXY 0 1\n"
        "Vertex\nProgram Three\nQuadXY 0 1\n"
        "Fragment\nProgram Fixed\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{"13:1: warning: Program Fixed has no shaders; set Vertex and Fragment first"});
    ASSERT_EQ(p.plan.programs.size(), 4u);
    const auto& one = p.plan.programs[0];
    ASSERT_EQ(one.stages.size(), 2u);
    EXPECT_EQ(one.stages[0].path, dir.path("shaders/a.vert"));
    EXPECT_EQ(one.stages[1].path, dir.path("shaders/a.frag"));
    EXPECT_FALSE(one.gstap);
    const auto& two = p.plan.programs[1];
    ASSERT_EQ(two.stages.size(), 2u);
    EXPECT_EQ(two.stages[1].path, dir.path("shaders/b.frag"));
    EXPECT_TRUE(two.gstap);
    const auto& three = p.plan.programs[2];
    ASSERT_EQ(three.stages.size(), 1u);
    EXPECT_EQ(three.stages[0].kind, ShaderStage::Kind::Fragment);
    EXPECT_TRUE(p.plan.programs[3].stages.empty());

    auto d = draws(p.plan.passes.at(0));
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[0]->program, 0);
    EXPECT_EQ(d[1]->program, 1);
    EXPECT_EQ(d[2]->program, 2);
    EXPECT_EQ(d[3]->program, -1);  // fixed function
}

TEST_F(PlanTest, StateIsRecordedPerDraw) {
    Planned p = run(
        "Background 0.1 0.2 0.3\nClear\n"
        "Color 1 0 0\nLineWidth 3\nPointSize 4\nFlat\nQuadXY 0 1\n"
        "Color [0 1 0 0.5]\nSmooth\nQuadXY 0 1\n"
        "Timer 4\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.passes.size(), 1u);
    const Pass& pass = p.plan.passes[0];
    ASSERT_EQ(pass.steps.size(), 3u);
    EXPECT_EQ(pass.steps[0].kind, Step::Kind::Clear);
    EXPECT_EQ(pass.steps[0].clearColor, glm::vec4(0.1f, 0.2f, 0.3f, 1.f));
    const Draw& a = pass.steps[1].draw;
    EXPECT_EQ(a.color, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(a.lineWidth, 3.f);
    EXPECT_EQ(a.pointSize, 4.f);
    EXPECT_TRUE(a.flatShading);
    const Draw& b = pass.steps[2].draw;
    EXPECT_EQ(b.color, glm::vec4(0, 1, 0, 0.5f));
    EXPECT_FALSE(b.flatShading);
    EXPECT_EQ(p.plan.timerPeriod, 4.0);
}

// ---- problems -----------------------------------------------------------------

TEST_F(PlanTest, PopMatrixWithoutPushIsWarned) {
    Planned p = run("Translate 1 0 0\nPopMatrix\nTransformEnd\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), (V{"2:1: warning: PopMatrix without a matching PushMatrix is ignored",
                                    "3:1: warning: TransformEnd without a matching PushMatrix is ignored"}));
    EXPECT_TRUE(matNear(draws(p.plan.passes.at(0)).at(0)->modelView,
                        glm::translate(glm::mat4(1), glm::vec3(1, 0, 0))));
}

TEST_F(PlanTest, FormerlyUnsupportedCommandsNowDraw) {
    // Teapot and CubeMap were "not supported yet" before glman parity.
    Planned p = run("Teapot\nCubeMap 4 img.bmp img.bmp img.bmp img.bmp img.bmp img.bmp\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.passes.size(), 1u);
    EXPECT_EQ(draws(p.plan.passes[0]).size(), 2u);
    EXPECT_EQ(p.plan.meshes.size(), 2u);
}

TEST_F(PlanTest, ArityErrors) {
    Planned p = run(
        "Translate 1\n"
        "Rotate 30\n"
        "LineWidth\n"
        "Scale 1 2\n"
        "Translate 1 foo 3\n"
        "LookAt 1 2 3\n"
        "QuadXY 1\n"
        "Sphere 1 2 3 4\n");
    EXPECT_EQ(messages(p.diags), (V{"1:1: error: Translate takes 2 to 3 numbers, got 1",
                                    "2:1: error: Rotate takes 4 numbers, got 1",
                                    "3:1: error: LineWidth takes 1 number, got 0",
                                    "4:1: error: Scale takes 3 numbers, got 2",
                                    "5:13: error: Translate takes numbers; 'foo' is not a number",
                                    "6:1: error: LookAt takes 9 numbers, got 3",
                                    "7:1: error: QuadXY takes 2 to 4 numbers, got 1",
                                    "8:1: error: Sphere takes 0 to 3 numbers, got 4"}));
    EXPECT_TRUE(p.plan.meshes.empty());
}

TEST_F(PlanTest, MessageBoxTextIsANoteOnTheNextProgram) {
    Planned p = run("Vertex a.vert\nFragment a.frag\nMessageBox Blur: the average of the neighbours\n"
                    "MessageBox (a cone of weights)\nProgram Blur\nProgram Plain\nQuadXY 0 1\n");
    EXPECT_EQ(errors(p.diags), V{});
    ASSERT_EQ(p.plan.programs.size(), 2u);
    EXPECT_EQ(p.plan.programs[0].notes, "Blur: the average of the neighbours\n(a cone of weights)");
    EXPECT_EQ(p.plan.programs[1].notes, "");  // each text goes to one Program only
}

// The panel shows a Program's notes under its name: only MessageBox text and
// the script's comments, never another command's arguments (a Timer's period).
TEST_F(PlanTest, ATimerBeforeAProgramIsNoNoteOnIt) {
    Planned p = run("Vertex a.vert\nFragment a.frag\nTimer 4\nProgram Spin\nQuadXY 0 1\n");
    EXPECT_EQ(messages(p.diags), V{});
    EXPECT_EQ(p.plan.timerPeriod, 4.0);
    ASSERT_EQ(p.plan.programs.size(), 1u);
    EXPECT_EQ(p.plan.programs[0].notes, "");
}

}  // namespace
}  // namespace glimmer::test
