// The glman commands added for parity (issue 3): texture kinds and where a
// texture command acts, the new shapes and their parameters, glBegin/glEnd,
// NumPatchVertices, noise sizes, tessellation stages, and the depth rule.
#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "plan_test_util.h"

namespace glimmer::test {
namespace {

using V = std::vector<std::string>;

class GlmanPlanTest : public ::testing::Test {
protected:
    Planned run(const std::string& text, const PlanOptions& o = {}) { return plan(dir.script(), text, o); }
    TempProject dir;
};

std::vector<std::string> notSupported(const Diagnostics& d) {
    std::vector<std::string> out;
    for (const auto& m : warnings(d))
        if (m.find("not supported") != std::string::npos) out.push_back(m);
    return out;
}

TEST_F(GlmanPlanTest, EveryNewShapeMakesOneDraw) {
    dir.touch("scripts/m.obj");
    const char* lines[] = {
        "Teapot", "WireTeapot", "Cone", "Cylinder 0.5 2", "DiskXY", "WireBox", "WireSphere", "WireTorus",
        "WireCone", "WireCylinder", "WireObj m.obj", "ObjAdj m.obj", "Triangles [0 0 0] [1 0 0] [0 1 0]",
        "LinesAdjacency [0 0 0] [1 0 0] [2 0 0] [3 0 0]", "PointCloud", "JitterCloud", "QuadBox",
    };
    for (const char* line : lines) {
        SCOPED_TRACE(line);
        Planned p = run(std::string(line) + "\n");
        EXPECT_EQ(messages(p.diags), V{});
        ASSERT_EQ(p.plan.passes.size(), 1u);
        EXPECT_EQ(draws(p.plan.passes[0]).size(), 1u);
        EXPECT_EQ(notSupported(p.diags), V{});
    }
}

TEST_F(GlmanPlanTest, ShapeDefaultsAreFilledIn) {
    Planned p = run("Cone\nCylinder 0.5 2\nDiskXY\nTeapot\nQuadBox\nPointCloud\nJitterCloud 4\nWireCone 2 3 12\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.meshes.size(), 8u);
    EXPECT_EQ(p.plan.meshes[0].params, (std::vector<double>{1, 1, 40}));
    EXPECT_EQ(p.plan.meshes[1].params, (std::vector<double>{0.5, 2, 40}));
    EXPECT_EQ(p.plan.meshes[2].params, (std::vector<double>{1, 40}));
    EXPECT_EQ(p.plan.meshes[3].params, (std::vector<double>{1, 10}));
    EXPECT_EQ(p.plan.meshes[4].params, (std::vector<double>{1}));
    EXPECT_EQ(p.plan.meshes[5].params, (std::vector<double>{1000, 1}));
    EXPECT_EQ(p.plan.meshes[6].params, (std::vector<double>{4, 1, 0.5}));
    EXPECT_EQ(p.plan.meshes[7].shape, CommandKind::WireCone);
    EXPECT_EQ(p.plan.meshes[7].params, (std::vector<double>{2, 3, 12}));
}

TEST_F(GlmanPlanTest, ShapeArgumentErrors) {
    Planned p = run("Cone 1 1 2\nTeapot 1 0\nPointCloud 0\nTriangles [0 0 0] [1 0 0]\nTriangles [0 0 0] 4 [1 1 1]\n");
    EXPECT_EQ(messages(p.diags),
              (V{"1:10: error: Cone's slices must be a whole number from 3 to 1000",
                 "2:10: error: Teapot's subdivisions must be a whole number from 1 to 300",
                 "3:12: error: PointCloud's count must be a whole number from 1 to 1000000",
                 "4:1: error: Triangles needs 3 points [x y z], got 2",
                 "5:19: error: Triangles takes points written [x y z]; '4' is not one"}));
    EXPECT_TRUE(p.plan.meshes.empty());
}

TEST_F(GlmanPlanTest, TrianglesKeepTheirPointsAndWarnAboutLeftovers) {
    Planned p = run("Triangles [0 0 0] [1 0 0] [0 1 0] [5 5 5]\nTriangles [0 0] [1 0] [0 1]\n");
    EXPECT_EQ(messages(p.diags), V{"1:35: warning: Triangles takes points in groups of 3; the last one is ignored"});
    ASSERT_EQ(p.plan.meshes.size(), 2u);
    EXPECT_EQ(p.plan.meshes[0].points, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5}));
    // [x y] lies at z = 0.
    EXPECT_EQ(p.plan.meshes[1].points, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
}

TEST_F(GlmanPlanTest, GlBeginCollectsVerticesIntoOneDrawWithTheStateAtGlBegin) {
    Planned p = run(
        "Color 1 0 0\n"
        "NumPatchVertices 4\n"
        "glBegin gl_patches\n"
        "glVertex 0 0 0\n"
        "glVertex 1 0 0\n"
        "glVertex 1 1 0 2\n"
        "glVertex 0 1\n"
        "glEnd\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.passes.size(), 1u);
    auto d = draws(p.plan.passes[0]);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0]->loc.line, 3);
    EXPECT_EQ(d[0]->patchVertices, 4);
    EXPECT_EQ(d[0]->color, glm::vec4(1, 0, 0, 1));
    const MeshDecl& m = p.plan.meshes.at(d[0]->mesh);
    EXPECT_EQ(m.shape, CommandKind::GlBegin);
    EXPECT_EQ(m.params, std::vector<double>{double(int(ImmediatePrimitive::Patches))});
    EXPECT_EQ(m.points, (std::vector<double>{0, 0, 0, 1, 0, 0, 0.5, 0.5, 0, 0, 1, 0}));
}

TEST_F(GlmanPlanTest, GlBeginProblems) {
    Planned p = run(
        "glVertex 0 0 0\n"         // 1: outside
        "glEnd\n"                  // 2: no glBegin
        "glBegin gl_blobs\n"       // 3: unknown primitive; its vertices are swallowed
        "glVertex 0 0 0\n"
        "glEnd\n"
        "glBegin GL_LINES\n"       // 6
        "glVertex 0 0 0\n"
        "Color 0 1 0\n"            // 8: acts after
        "glVertex 1 1 1\n"
        "glEnd\n"
        "glBegin lines\n"          // 11: never ended
        "glVertex 0 0 0\n"
        "glVertex 0 1 0\n");
    EXPECT_EQ(messages(p.diags),
              (V{"1:1: warning: glVertex outside glBegin ... glEnd; ignored",
                 "2:1: warning: glEnd without glBegin; ignored",
                 "3:9: error: glBegin takes one primitive: gl_points, gl_lines, gl_line_strip, gl_line_loop, "
                 "gl_triangles, gl_triangle_strip, gl_triangle_fan, gl_quads, gl_quad_strip, gl_polygon or "
                 "gl_patches; not 'gl_blobs'",
                 "8:1: warning: only glVertex belongs between glBegin (line 6) and glEnd; Color acts here, on what "
                 "is drawn after it, not on this glBegin",
                 "11:1: warning: glBegin without glEnd; drawn as if the script ended it"}));
    auto d = draws(p.plan.passes.at(0));
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0]->color, glm::vec4(1));     // the state at its glBegin
    EXPECT_EQ(d[1]->color, glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(p.plan.meshes.at(d[1]->mesh).points, (std::vector<double>{0, 0, 0, 0, 1, 0}));
}

TEST_F(GlmanPlanTest, TextureKindsAndTheSkyboxIdiom) {
    dir.touch("textures/vol.tex");
    Planned p = run(
        "Texture2D 6 img.bmp\n"
        "QuadXY 0 1\n"
        "Texture2D 6 other.bmp\n"
        "QuadXZ 0 1\n"
        "CubeMap 6 img.bmp other.bmp img.bmp other.bmp img.bmp other.bmp\n"
        "Sphere\n"
        "Texture3D 7 vol.tex\n"
        "Texture3D 8 16 8 4\n"
        "Texture2D 6 img.bmp\n"
        "QuadYZ 0 1\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.textures.size(), 5u);
    using K = TextureDecl::Kind;
    EXPECT_EQ(p.plan.textures[0].kind, K::Tex2D);
    EXPECT_EQ(p.plan.textures[2].kind, K::Cube);
    EXPECT_EQ(p.plan.textures[2].facePaths.size(), 6u);
    EXPECT_EQ(p.plan.textures[2].facePaths[1], dir.path("textures/other.bmp"));
    EXPECT_EQ(p.plan.textures[2].faceShown[1], "other.bmp");
    EXPECT_EQ(p.plan.textures[3].kind, K::Tex3D);
    EXPECT_EQ(p.plan.textures[3].source, TextureDecl::Source::File);
    EXPECT_EQ(p.plan.textures[4].kind, K::Tex3D);
    EXPECT_EQ(p.plan.textures[4].depth, 4);
    // Each draw sees unit 6 as the script left it at that line; the last
    // Texture2D shares the first texture (same file).
    auto d = draws(p.plan.passes.at(0));
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[0]->units.at(6), 0);
    EXPECT_EQ(d[1]->units.at(6), 1);
    EXPECT_EQ(d[2]->units.at(6), 2);
    EXPECT_EQ(d[3]->units.at(6), 0);
    EXPECT_EQ(d[3]->units.at(7), 3);
}

TEST_F(GlmanPlanTest, TextureCommandErrors) {
    Planned p = run(
        "CubeMap 6 img.bmp img.bmp\n"
        "CubeMap 6 img.bmp img.bmp img.bmp img.bmp img.bmp nothere.bmp\n"
        "Texture3D 5 4 4\n"
        "Texture3D 5 4 4 0\n"
        "CubeMap 6 img.bmp img.bmp img.bmp img.bmp img.bmp img.bmp\n"
        "RenderToTexture 6\n"
        "CubeMap 6\n");
    auto e = errors(p.diags);
    ASSERT_EQ(e.size(), 6u);
    EXPECT_EQ(e[0], "CubeMap needs a unit and six files, +x -x +y -y +z -z; got 3 arguments");
    EXPECT_EQ(e[1].rfind("cannot find texture 'nothere.bmp'", 0), 0u) << e[1];
    EXPECT_EQ(e[2], "Texture3D needs a unit and a raw .tex file, or a unit, a width, a height and a depth");
    EXPECT_EQ(e[3], "a texture's size must be between 1 and 2048 each way");
    EXPECT_EQ(e[4], "unit 6 holds a cube map; render into an empty texture made with Texture2D 6 width height");
    EXPECT_EQ(e[5], "CubeMap needs a unit and six files, +x -x +y -y +z -z; got 1 argument");  // one, not "1 arguments"
}

TEST_F(GlmanPlanTest, TessellationStagesJoinTheProgram) {
    dir.touch("shaders/a.tesc");
    dir.touch("shaders/a.tese");
    dir.touch("shaders/a.geom");
    Planned p = run(
        "Vertex a.vert\nTessControl a.tesc\nTessEvaluation a.tese\nGeometry a.geom\nFragment a.frag\n"
        "Program T\n"
        "TessControl\nTessEvaluation\n"
        "Program G\n");
    EXPECT_EQ(messages(p.diags), V{});
    ASSERT_EQ(p.plan.programs.size(), 2u);
    EXPECT_EQ(p.plan.programs[0].stages.size(), 5u);
    ASSERT_EQ(p.plan.programs[1].stages.size(), 3u);
    for (const auto& s : p.plan.programs[1].stages) {
        EXPECT_NE(s.kind, ShaderStage::Kind::TessControl);
        EXPECT_NE(s.kind, ShaderStage::Kind::TessEvaluation);
    }
}

TEST_F(GlmanPlanTest, NoiseResolutions) {
    Planned d = run("QuadXY 0 1\n");
    EXPECT_EQ(d.plan.noise2DRes, 64);
    EXPECT_EQ(d.plan.noise3DRes, 64);
    Planned p = run("Noise2D 128\nNoise3D 32\nNoise3D 0\nNoise2D 1.5\n");
    EXPECT_EQ(p.plan.noise2DRes, 128);
    EXPECT_EQ(p.plan.noise3DRes, 32);
    EXPECT_EQ(errors(p.diags), (V{"Noise3D's resolution must be a whole number from 1 to 512",
                                  "Noise2D's resolution must be a whole number from 1 to 4096"}));
}

TEST_F(GlmanPlanTest, DepthForSolidShapesOnly) {
    auto depth = [&](const std::string& text) {
        Planned p = run(text);
        EXPECT_EQ(errors(p.diags), V{}) << text;
        return !p.plan.passes.empty() && p.plan.passes[0].needsDepth;
    };
    EXPECT_FALSE(depth("DiskXY\n"));
    EXPECT_FALSE(depth("Triangles [0 0 0] [1 0 0] [0 1 0] [0 0 0] [1 1 0] [0 1 0]\n"));
    EXPECT_FALSE(depth("glBegin gl_quads\nglVertex 0 0 1\nglVertex 1 0 1\nglVertex 1 1 1\nglVertex 0 1 1\nglEnd\n"));
    EXPECT_TRUE(depth("Triangles [0 0 0] [1 0 0] [0 1 0] [0 0 1] [1 0 1] [0 1 1]\n"));
    EXPECT_TRUE(depth("Cone\n"));
    EXPECT_TRUE(depth("Cylinder\n"));
    EXPECT_TRUE(depth("Teapot\n"));
    EXPECT_TRUE(depth("QuadBox\n"));
    EXPECT_TRUE(depth("WireSphere\n"));
}

TEST_F(GlmanPlanTest, NumPatchVerticesChecksItsArgument) {
    Planned p = run("NumPatchVertices 0\nNumPatchVertices 33\nNumPatchVertices 16\nglBegin gl_patches\nglVertex 0 0 0\nglEnd\n");
    EXPECT_EQ(errors(p.diags), (V{"NumPatchVertices takes a whole number from 1 to 32",
                                  "NumPatchVertices takes a whole number from 1 to 32"}));
    EXPECT_EQ(draws(p.plan.passes.at(0)).at(0)->patchVertices, 16);
}

}  // namespace
}  // namespace glimmer::test
