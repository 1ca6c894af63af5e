#include <cmath>
#include <set>
#include <utility>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "mesh_checks.h"

namespace glimmer {
namespace {

using test::boundsOf;
using test::expectUnitNormals;
using test::expectVec3Near;
using test::expectWindingMatchesNormals;

// Sums triangle areas: catches missing, doubled or overlapping triangles that
// counts alone would not.
float area(const Mesh& m) {
    float a = 0.f;
    for (size_t t = 0; t < m.indices.size() / 3; ++t)
        a += .5f * glm::length(test::geometricNormal(m, t));
    return a;
}

// ---- quads -------------------------------------------------------------------

TEST(QuadXY, SingleQuadCountsBoundsAndAttributes) {
    const Mesh m = makeQuadXY(.5f, 2.f);
    ASSERT_EQ(m.vertices.size(), 4u);
    ASSERT_EQ(m.indices.size(), 6u);
    EXPECT_TRUE(m.flat);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, {-2.f, -2.f, .5f});
    expectVec3Near(b.hi, {2.f, 2.f, .5f});
    EXPECT_EQ(b.stLo, glm::vec2(0.f));
    EXPECT_EQ(b.stHi, glm::vec2(1.f));
    for (const MeshVertex& v : m.vertices) {
        EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
        EXPECT_EQ(v.tangent, glm::vec3(0, 1, 0));
    }
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 16.f, 1e-4f);
}

TEST(QuadXY, SubdividedGridAndTextureCoordinates) {
    const float size = 3.f;
    const Mesh m = makeQuadXY(-1.f, size, 3, 2);
    ASSERT_EQ(m.vertices.size(), 4u * 3u);
    ASSERT_EQ(m.indices.size(), 3u * 2u * 3u * 2u);
    std::set<std::pair<int, int>> cells;
    for (const MeshVertex& v : m.vertices) {
        EXPECT_FLOAT_EQ(v.position.z, -1.f);
        EXPECT_NEAR(v.st.s, (v.position.x + size) / (2.f * size), 1e-6f);
        EXPECT_NEAR(v.st.t, (v.position.y + size) / (2.f * size), 1e-6f);
        // Grid lines: s in thirds, t in halves.
        const float i = v.st.s * 3.f, j = v.st.t * 2.f;
        EXPECT_NEAR(i, std::round(i), 1e-5f);
        EXPECT_NEAR(j, std::round(j), 1e-5f);
        cells.insert({int(std::round(i)), int(std::round(j))});
    }
    EXPECT_EQ(cells.size(), 12u);  // every grid point exactly once
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 36.f, 1e-3f);
}

TEST(QuadXY, CountsBelowOneMeanOne) {
    const Mesh m = makeQuadXY(0.f, 1.f, 0, -3);
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.indices.size(), 6u);
    EXPECT_NEAR(area(m), 4.f, 1e-5f);
}

TEST(QuadXZ, PlaneNormalWindingAndST) {
    const float size = 2.f;
    const Mesh m = makeQuadXZ(1.5f, size, 2, 4);
    ASSERT_EQ(m.vertices.size(), 3u * 5u);
    ASSERT_EQ(m.indices.size(), 2u * 4u * 6u);
    EXPECT_TRUE(m.flat);
    for (const MeshVertex& v : m.vertices) {
        EXPECT_FLOAT_EQ(v.position.y, 1.5f);
        EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
        EXPECT_NEAR(v.st.s, (v.position.x + size) / (2.f * size), 1e-6f);
        EXPECT_NEAR(v.st.t, (v.position.z + size) / (2.f * size), 1e-6f);
    }
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, {-2.f, 1.5f, -2.f});
    expectVec3Near(b.hi, {2.f, 1.5f, 2.f});
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 16.f, 1e-3f);
}

TEST(QuadYZ, PlaneNormalWindingAndST) {
    const float size = 1.f;
    const Mesh m = makeQuadYZ(-2.f, size, 3, 1);
    ASSERT_EQ(m.vertices.size(), 4u * 2u);
    ASSERT_EQ(m.indices.size(), 3u * 6u);
    for (const MeshVertex& v : m.vertices) {
        EXPECT_FLOAT_EQ(v.position.x, -2.f);
        EXPECT_EQ(v.normal, glm::vec3(1, 0, 0));
        EXPECT_NEAR(v.st.s, (v.position.y + size) / (2.f * size), 1e-6f);
        EXPECT_NEAR(v.st.t, (v.position.z + size) / (2.f * size), 1e-6f);
    }
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, {-2.f, -1.f, -1.f});
    expectVec3Near(b.hi, {-2.f, 1.f, 1.f});
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 4.f, 1e-4f);
}

// ---- sphere ------------------------------------------------------------------

TEST(Sphere, CountsRadiusAndUnitNormals) {
    const float r = 2.5f;
    const Mesh m = makeSphere(r, 24, 12);
    EXPECT_TRUE(m.hasTangents);
    EXPECT_FALSE(m.flat);
    ASSERT_EQ(m.vertices.size(), 25u * 13u);
    ASSERT_EQ(m.indices.size(), 3u * 2u * 24u * 11u);
    for (const MeshVertex& v : m.vertices) {
        EXPECT_NEAR(glm::length(v.position), r, 1e-5f);
        expectVec3Near(v.normal, v.position / r);
    }
    expectUnitNormals(m);
    const auto b = boundsOf(m);
    EXPECT_NEAR(b.lo.y, -r, 1e-6f);
    EXPECT_NEAR(b.hi.y, r, 1e-6f);
    EXPECT_EQ(b.stLo, glm::vec2(0.f));
    EXPECT_EQ(b.stHi, glm::vec2(1.f));
    EXPECT_NEAR(area(m), 4.f * glm::pi<float>() * r * r, .02f * 4.f * glm::pi<float>() * r * r);
}

TEST(Sphere, WindingIsCounterClockwiseFromOutside) {
    expectWindingMatchesNormals(makeSphere());
    expectWindingMatchesNormals(makeSphere(1.f, 3, 2));  // the coarsest allowed
    expectWindingMatchesNormals(makeSphere(1.f, 1, 1));  // raised to 3 x 2
}

TEST(Sphere, TextureCoordinatesFollowLongitudeAndLatitude) {
    const int slices = 16, stacks = 8;
    const Mesh m = makeSphere(1.f, slices, stacks);
    const float pi = glm::pi<float>();
    for (int j = 0; j <= stacks; ++j) {
        for (int i = 0; i <= slices; ++i) {
            const MeshVertex& v = m.vertices[j * (slices + 1) + i];
            // t = 0 south, 1 north.
            EXPECT_NEAR(v.position.y, std::sin(-pi / 2.f + pi * v.st.t), 1e-5f);
            if (j == 0 || j == stacks) continue;
            // Longitude 0 (s = .5) at +Z, +pi/2 (s = .75) at +X.
            const float lng = std::atan2(v.position.x, v.position.z);
            const float expected = -pi + 2.f * pi * v.st.s;
            EXPECT_NEAR(std::remainder(lng - expected, 2.f * pi), 0.f, 1e-4f) << i << "," << j;
        }
        // The seam column repeats the first one with s = 1.
        const MeshVertex& first = m.vertices[j * (slices + 1)];
        const MeshVertex& last = m.vertices[j * (slices + 1) + slices];
        expectVec3Near(first.position, last.position);
        EXPECT_EQ(first.st.s, 0.f);
        EXPECT_EQ(last.st.s, 1.f);
        EXPECT_EQ(first.st.t, last.st.t);
    }
    // A viewer on +Z sees the middle of the texture.
    const MeshVertex& front = m.vertices[(stacks / 2) * (slices + 1) + slices / 2];
    expectVec3Near(front.position, {0.f, 0.f, 1.f});
}

TEST(Sphere, TangentsAreUnitOrthogonalAndPointNorth) {
    const Mesh m = makeSphere(3.f, 20, 10);
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const MeshVertex& v = m.vertices[i];
        EXPECT_TRUE(std::isfinite(v.tangent.x) && std::isfinite(v.tangent.y) &&
                    std::isfinite(v.tangent.z));
        EXPECT_NEAR(glm::length(v.tangent), 1.f, 1e-5f) << i;
        EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.f, 1e-5f) << i;
        EXPECT_GE(v.tangent.y, 0.f) << i;
    }
}

TEST(Sphere, TangentIsTheLatitudeDerivative) {
    const int slices = 20, stacks = 10;
    const Mesh m = makeSphere(3.f, slices, stacks);
    auto at = [&](int i, int j) { return m.vertices[j * (slices + 1) + i]; };
    // On a meridian the chord between the neighbours above and below is
    // parallel to the tangent at the middle vertex.
    for (auto [i, j] : {std::pair{0, 5}, {3, 1}, {7, 8}, {13, 4}, {20, 9}}) {
        const glm::vec3 chord = glm::normalize(at(i, j + 1).position - at(i, j - 1).position);
        expectVec3Near(at(i, j).tangent, chord);
    }
    // At a pole, the limit along the vertex's own meridian: horizontal, along
    // the step from the south pole to the next row, and along the step from
    // the last row over the north pole.
    auto horizontal = [](glm::vec3 v) { return glm::normalize(glm::vec3(v.x, 0.f, v.z)); };
    for (int i : {0, 4, 11, 20}) {
        expectVec3Near(at(i, 0).tangent, horizontal(at(i, 1).position - at(i, 0).position));
        expectVec3Near(at(i, stacks).tangent,
                       horizontal(at(i, stacks).position - at(i, stacks - 1).position));
    }
}

// ---- torus -------------------------------------------------------------------

TEST(Torus, CountsAndRadii) {
    const float R = 2.f, r = .5f;
    const Mesh m = makeTorus(R, r, 12, 32);  // multiples of 4 put vertices on the extremes
    ASSERT_EQ(m.vertices.size(), 33u * 13u);
    ASSERT_EQ(m.indices.size(), 6u * 12u * 32u);
    for (const MeshVertex& v : m.vertices) {
        const glm::vec2 xy(v.position.x, v.position.y);
        const float ring = glm::length(xy);
        // Distance to the ring circle (radius R in the XY plane) is the tube radius.
        EXPECT_NEAR(std::hypot(ring - R, v.position.z), r, 1e-5f);
        // The normal points from the nearest ring point out to the surface.
        const glm::vec3 centre = glm::vec3(R * xy / ring, 0.f);
        expectVec3Near(v.normal, (v.position - centre) / r);
        EXPECT_NEAR(glm::dot(v.tangent, v.normal), 0.f, 1e-5f);
    }
    expectUnitNormals(m);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, {-(R + r), -(R + r), -r}, 1e-4f);
    expectVec3Near(b.hi, {R + r, R + r, r}, 1e-4f);
    EXPECT_EQ(b.stLo, glm::vec2(0.f));
    EXPECT_EQ(b.stHi, glm::vec2(1.f));
    const float exact = 4.f * glm::pi<float>() * glm::pi<float>() * R * r;
    EXPECT_NEAR(area(m), exact, .03f * exact);
}

TEST(Torus, DefaultsWindingAndParameterDirections) {
    const Mesh m = makeTorus();  // [1 .5 20 40]
    ASSERT_EQ(m.vertices.size(), 41u * 21u);
    expectWindingMatchesNormals(m);
    auto at = [&](int i, int j) { return m.vertices[j * 41 + i].position; };
    expectVec3Near(at(0, 0), {1.5f, 0.f, 0.f});   // s = t = 0 on the outer equator at +X
    expectVec3Near(at(10, 0), {0.f, 1.5f, 0.f});  // s = .25 a quarter of the way, at +Y
    expectVec3Near(at(0, 5), {1.f, 0.f, .5f});    // t = .25 on top of the tube
    expectVec3Near(at(0, 10), {.5f, 0.f, 0.f});   // t = .5 on the inner equator
}

// ---- box ---------------------------------------------------------------------

TEST(Box, DefaultIsTheUnitCube) {
    const Mesh m = makeBox();
    ASSERT_EQ(m.vertices.size(), 24u);
    ASSERT_EQ(m.indices.size(), 36u);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, glm::vec3(-1.f));
    expectVec3Near(b.hi, glm::vec3(1.f));
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 24.f, 1e-4f);
}

TEST(Box, FacesHaveTheirOwnNormalsAndFullTextureSquare) {
    const glm::vec3 d{2.f, 4.f, 6.f};
    const Mesh m = makeBox(d.x, d.y, d.z);
    ASSERT_EQ(m.vertices.size(), 24u);
    std::set<std::tuple<float, float, float>> normals;
    for (size_t f = 0; f < 6; ++f) {
        const glm::vec3 n = m.vertices[f * 4].normal;
        normals.insert({n.x, n.y, n.z});
        EXPECT_NEAR(glm::length(n), 1.f, 1e-6f);
        EXPECT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.f);  // axis-aligned
        std::set<std::pair<float, float>> corners;
        for (size_t k = 0; k < 4; ++k) {
            const MeshVertex& v = m.vertices[f * 4 + k];
            EXPECT_EQ(v.normal, n);
            // On the face plane, half the extent out along its normal.
            EXPECT_NEAR(glm::dot(v.position, n), glm::dot(d / 2.f, glm::abs(n)), 1e-6f);
            EXPECT_NEAR(glm::dot(v.tangent, n), 0.f, 1e-6f);
            corners.insert({v.st.s, v.st.t});
        }
        const std::set<std::pair<float, float>> square{{0.f, 0.f}, {1.f, 0.f}, {0.f, 1.f}, {1.f, 1.f}};
        EXPECT_EQ(corners, square) << "face " << f;
    }
    EXPECT_EQ(normals.size(), 6u);
    // Each face's two triangles use only that face's vertices.
    for (size_t t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(m.indices[t * 3 + k] / 4, t / 2);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, -d / 2.f);
    expectVec3Near(b.hi, d / 2.f);
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 2.f * (d.x * d.y + d.y * d.z + d.x * d.z), 1e-3f);
}

}  // namespace
}  // namespace glimmer
