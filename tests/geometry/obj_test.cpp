#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "mesh_checks.h"

namespace glimmer {
namespace {

namespace fs = std::filesystem;
using test::expectUnitNormals;
using test::expectVec3Near;
using test::expectWindingMatchesNormals;

// Each test writes its own file so that parallel ctest runs do not collide.
class ObjTest : public ::testing::Test {
protected:
    std::string write(const std::string& text) {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::path(::testing::TempDir()) /
                (std::string("glimmer_") + info->name() + "_" + std::to_string(::getpid()) + ".obj");
        std::ofstream(path_) << text;
        return path_.string();
    }
    void TearDown() override {
        if (!path_.empty()) fs::remove(path_);
    }
    fs::path path_;
};

// A unit quad in z = 0 and a pentagon in the plane x = 2, both CCW from their
// front (+Z and +X).
const char* kPolygons = R"(# quad and pentagon
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 2 0 0
v 2 1 0
v 2 1.5 .5
v 2 1 1
v 2 0 1
f 1 2 3 4
f 5 6 7 8 9
)";

TEST_F(ObjTest, PolygonsBecomeTrianglesWithFaceNormals) {
    Mesh m;
    std::string error;
    ASSERT_TRUE(loadObj(write(kPolygons), m, error)) << error;
    ASSERT_EQ(m.indices.size(), 3u * (2u + 3u));
    EXPECT_FALSE(m.hasTangents);
    expectWindingMatchesNormals(m);
    expectUnitNormals(m);
    // Quad triangles first, then the pentagon's.
    for (size_t k = 0; k < 6; ++k) expectVec3Near(m.vertices[m.indices[k]].normal, {0, 0, 1});
    for (size_t k = 6; k < 15; ++k) expectVec3Near(m.vertices[m.indices[k]].normal, {1, 0, 0});
    // The triangles cover the polygons exactly: 1 + (1 + .25).
    float area = 0.f;
    for (size_t t = 0; t < 5; ++t) area += .5f * glm::length(test::geometricNormal(m, t));
    EXPECT_NEAR(area, 2.25f, 1e-5f);
    const auto b = test::boundsOf(m);
    expectVec3Near(b.lo, {0, 0, 0});
    expectVec3Near(b.hi, {2, 1.5f, 1});
}

TEST_F(ObjTest, NormalsFromVnAreUsedAndNormalized) {
    // The vn deliberately disagree with the face normal (but stay on its
    // side) and are not unit length.
    const std::string text = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 2
vn 0 1 1
f 1//1 2//1 3//2 4//2
)";
    Mesh m;
    std::string error;
    ASSERT_TRUE(loadObj(write(text), m, error)) << error;
    ASSERT_EQ(m.indices.size(), 6u);
    for (std::uint32_t i : m.indices) {
        const MeshVertex& v = m.vertices[i];
        const glm::vec3 expected =
            v.position.y == 0.f ? glm::vec3(0, 0, 1) : glm::normalize(glm::vec3(0, 1, 1));
        expectVec3Near(v.normal, expected);
    }
    expectWindingMatchesNormals(m);
    // Corners shared by the two triangles are shared vertices too.
    EXPECT_EQ(m.vertices.size(), 4u);
}

TEST_F(ObjTest, TextureCoordinates) {
    const std::string text = R"(v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt .5 0
vt .5 .25
vt 0 .25
f 1/1 2/2 3/3 4/4
)";
    Mesh m;
    std::string error;
    ASSERT_TRUE(loadObj(write(text), m, error)) << error;
    ASSERT_EQ(m.indices.size(), 6u);
    for (std::uint32_t i : m.indices) {
        const MeshVertex& v = m.vertices[i];
        EXPECT_FLOAT_EQ(v.st.s, (v.position.x + 1.f) / 4.f);
        EXPECT_FLOAT_EQ(v.st.t, (v.position.y + 1.f) / 8.f);
        expectVec3Near(v.normal, {0, 0, 1});
    }
}

TEST_F(ObjTest, MissingFileNamesPathAndReason) {
    const std::string path = (fs::path(::testing::TempDir()) / "glimmer_no_such_file.obj").string();
    Mesh m;
    m.vertices.resize(3);
    std::string error;
    EXPECT_FALSE(loadObj(path, m, error));
    EXPECT_NE(error.find(path), std::string::npos) << error;
    EXPECT_NE(error.find("cannot open: No such file or directory"), std::string::npos) << error;
    EXPECT_EQ(m.vertices.size(), 3u);  // left alone on failure
}

TEST_F(ObjTest, FileWithoutFacesIsAnError) {
    Mesh m;
    std::string error;
    const std::string path = write("v 0 0 0\nv 1 0 0\n");
    EXPECT_FALSE(loadObj(path, m, error));
    EXPECT_NE(error.find(path), std::string::npos) << error;
}

}  // namespace
}  // namespace glimmer

namespace glimmer {
namespace {

// What an OBJ asks for, counted before tinyobjloader sees it (issue 30).
TEST(ObjCounts, CountsLinesCornersAndTheTrianglesFacesBecome) {
    ObjCounts c = countObj("# a quad and a pentagon\nv 0 0 0\nv 1 0 0\n  v 1 1 0\nvt 0 0\nvn 0 0 1\n"
                           "f 1 2 3 1\nf\t1/1/1 2/1/1 3/1/1 1 2\r\nvertex 1\n");
    EXPECT_EQ(c.positions, 3u);
    EXPECT_EQ(c.texcoords, 1u);
    EXPECT_EQ(c.normals, 1u);
    EXPECT_EQ(c.triangles, 2u + 3u);
    EXPECT_EQ(c.mostCorners, 5u);
    EXPECT_EQ(c.mostCornersLine, 8);
    EXPECT_EQ(c.cuttingWork, 25u);  // only the pentagon: quads and triangles are cut at once
    EXPECT_GE(c.bytes, 5u * 3u * sizeof(MeshVertex));
}

TEST(ObjCounts, AFaceOfTooManyCornersIsRefusedBeforeParsing) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 1001; ++i) text += " " + std::to_string(1 + i % 3);
    Mesh m;
    std::string error;
    EXPECT_FALSE(loadObjText(text + "\n", countObj(text + "\n"), "fan.obj", m, error));
    EXPECT_EQ(error, "cannot load OBJ 'fan.obj': the face on its line 4 has 1001 corners; Glimmer cuts faces of at "
                     "most 1000 corners into triangles");
}

TEST(ObjCounts, ManyLargeFacesAreRefusedTogether) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n", face = "f";
    for (int i = 0; i < 1000; ++i) face += " " + std::to_string(1 + i % 3);
    for (int k = 0; k < 101; ++k) text += face + "\n";  // 101 x 1000^2 > 10^8
    Mesh m;
    std::string error;
    EXPECT_FALSE(loadObjText(text, countObj(text), "many.obj", m, error));
    EXPECT_EQ(error, "cannot load OBJ 'many.obj': its faces of five corners or more are too many to cut into "
                     "triangles (corners squared add up to 101000000, at most 100000000); split them in the modeller");
}

TEST(ObjCounts, MeshBytesCountBothCopies) {
    Mesh m;
    m.vertices.resize(10);
    m.indices.resize(30);
    EXPECT_EQ(meshBytes(m), 2u * (10u * sizeof(MeshVertex) + 30u * 4u));
}

}  // namespace
}  // namespace glimmer
