#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "geometry/teapot_data.h"
#include "mesh_checks.h"
#include "topology_checks.h"

namespace glimmer {
namespace {

using test::boundsOf;

glm::vec3 controlPoint(int patch, int k) {
    const float* v = teapot::kVertices[teapot::kPatches[patch][k] - 1];
    return {v[0], v[1], v[2]};
}

// ---- the published data ---------------------------------------------------------

TEST(TeapotData, IndicesInRangeAndUsage) {
    std::set<int> used;
    for (const auto& patch : teapot::kPatches)
        for (std::uint16_t i : patch) {
            ASSERT_GE(i, 1);
            ASSERT_LE(i, teapot::kNumVertices);
            used.insert(i);
        }
    // Every listed point but 205, 206, 216, 223 (tiny offsets at the lid's tip).
    EXPECT_EQ(used.size(), 302u);
    for (int unused : {205, 206, 216, 223}) EXPECT_EQ(used.count(unused), 0u);
    // Heights stay in the published range; the bottom centre is the origin.
    for (const auto& v : teapot::kVertices) {
        EXPECT_GE(v[2], 0.f);
        EXPECT_LE(v[2], 3.15f);
    }
    EXPECT_EQ(controlPoint(teapot::kBottom, 0), glm::vec3(0.f));
}

// Rim, body, lid and bottom are four quarter turns of one patch each: patch
// k+1 is patch k turned 90 degrees about Z (same control point order).
TEST(TeapotData, QuartersAreRotations) {
    auto turn = [](glm::vec3 p, int dir) { return glm::vec3(dir * p.y, -dir * p.x, p.z); };
    for (int first : {teapot::kRim, teapot::kBody, teapot::kBody + 4, teapot::kLid, teapot::kLid + 4,
                      teapot::kBottom}) {
        const int dir = first == teapot::kBottom ? -1 : 1;  // the bottom runs the other way round
        for (int q = 0; q < 3; ++q)
            for (int k = 0; k < 16; ++k) {
                const glm::vec3 expect = turn(controlPoint(first + q, k), dir);
                const glm::vec3 got = controlPoint(first + q + 1, k);
                ASSERT_NEAR(glm::length(got - expect), 0.f, 1e-6f)
                    << "patch " << first + q + 1 << " point " << k;
            }
    }
}

// Handle and spout: the second patch of each pair mirrors the first in y,
// each row reversed.
TEST(TeapotData, HandleAndSpoutHalvesAreMirrors) {
    for (int first : {teapot::kHandle, teapot::kHandle + 2, teapot::kSpout, teapot::kSpout + 2})
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col) {
                const glm::vec3 a = controlPoint(first, row * 4 + 3 - col);
                const glm::vec3 b = controlPoint(first + 1, row * 4 + col);
                ASSERT_EQ(b, glm::vec3(a.x, -a.y, a.z)) << "patch " << first + 1 << " row " << row;
            }
}

// ---- the mesh --------------------------------------------------------------------

TEST(Teapot, Counts) {
    for (int n : {1, 4, 10}) {
        const Mesh m = makeTeapot(1.f, n);
        EXPECT_EQ(m.primitive, Mesh::Primitive::Triangles);
        EXPECT_EQ(m.vertices.size(), 32u * (n + 1) * (n + 1));
        EXPECT_EQ(m.indices.size(), 32u * n * n * 2 * 3);
        EXPECT_TRUE(m.hasTangents);
        EXPECT_FALSE(m.flat);
    }
    EXPECT_EQ(makeTeapot().indices.size(), 32u * 100u * 6u);
    EXPECT_EQ(makeTeapot(1.f, 0).indices.size(), 32u * 6u);  // at least 1
}

TEST(Teapot, FiniteUnitNormalsAndTangents) {
    const Mesh m = makeTeapot(1.f, 10);
    test::expectFinite(m);
    test::expectUnitNormals(m);
    for (const MeshVertex& v : m.vertices) ASSERT_NEAR(glm::length(v.tangent), 1.f, 1e-4f);
}

TEST(Teapot, GlutOrientationAndSize) {
    const Mesh m = makeTeapot(1.f, 10);
    const auto b = boundsOf(m);
    // Y up: bottom at Newell z = 0, lid tip at 3.15, both through (z - 1.5) / 2.
    EXPECT_NEAR(b.lo.y, -.75f, 1e-5f);
    EXPECT_NEAR(b.hi.y, .825f, 1e-5f);
    // Body radius 2 (Newell), halved; the body is widest along Z.
    EXPECT_NEAR(b.lo.z, -1.f, 1e-5f);
    EXPECT_NEAR(b.hi.z, 1.f, 1e-5f);
    // Spout to +X, handle to -X.
    EXPECT_GT(b.hi.x, 1.55f);
    EXPECT_LT(b.hi.x, 1.7625f);
    EXPECT_NEAR(b.lo.x, -1.5f, 1e-5f);  // the handle's outer corner (-3, 0, 1.8)
    const float width = b.hi.x - b.lo.x, height = b.hi.y - b.lo.y;
    EXPECT_GT(width / height, 1.8f);
    EXPECT_LT(width / height, 2.2f);
    // `size` scales every position, nothing else.
    const Mesh big = makeTeapot(3.f, 10);
    ASSERT_EQ(big.vertices.size(), m.vertices.size());
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        test::expectVec3Near(big.vertices[i].position, 3.f * m.vertices[i].position, 1e-5f);
        ASSERT_EQ(big.vertices[i].normal, m.vertices[i].normal);
        ASSERT_EQ(big.vertices[i].st, m.vertices[i].st);
    }
}

TEST(Teapot, TextureCoordinatesArePatchParameters) {
    const int n = 4;
    const Mesh m = makeTeapot(1.f, n);
    for (size_t p = 0; p < 32; ++p)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const MeshVertex& v = m.vertices[p * (n + 1) * (n + 1) + j * (n + 1) + i];
                ASSERT_FLOAT_EQ(v.st.s, float(i) / n);
                ASSERT_FLOAT_EQ(v.st.t, float(j) / n);
            }
    // Patch corners are their corner control points (Bezier interpolation),
    // turned Y up and scaled by 1/2.
    for (int p = 0; p < 32; ++p) {
        const glm::vec3 c = controlPoint(p, 15);
        const MeshVertex& v = m.vertices[p * (n + 1) * (n + 1) + (n + 1) * (n + 1) - 1];
        test::expectVec3Near(v.position, .5f * glm::vec3(c.x, c.z - 1.5f, -c.y), 1e-5f);
    }
}

TEST(Teapot, NormalsPointOutward) {
    const int n = 10;
    const Mesh m = makeTeapot(1.f, n);
    const size_t perPatch = size_t(n + 1) * (n + 1);
    glm::vec3 centroid{0.f};
    for (const MeshVertex& v : m.vertices) centroid += v.position / float(m.vertices.size());
    // Body: every normal points away from the axis and from the centre.
    for (size_t i = teapot::kBody * perPatch; i < (teapot::kBody + 8) * perPatch; ++i) {
        const MeshVertex& v = m.vertices[i];
        ASSERT_GT(glm::dot(v.normal, glm::vec3(v.position.x, 0.f, v.position.z)), 0.f) << "vertex " << i;
        ASSERT_GT(glm::dot(v.normal, v.position - centroid), 0.f) << "vertex " << i;
    }
    // So does the lid around its knob and the whole bottom.
    for (int p : {24, 25, 26, 27, 28, 29, 30, 31})
        for (size_t i = p * perPatch; i < (p + 1) * perPatch; ++i)
            ASSERT_GT(glm::dot(m.vertices[i].normal, m.vertices[i].position - centroid), 0.f) << "patch " << p;
    // The bottom faces down, turning sideways only where it rounds up into
    // the body (its last row, t = 1, is vertical there).
    for (size_t i = teapot::kBottom * perPatch; i < m.vertices.size(); ++i) {
        const MeshVertex& v = m.vertices[i];
        ASSERT_LT(v.normal.y, v.st.t < 1.f ? 0.f : 1e-5f) << "vertex " << i;
        if (v.st.t <= .5f) {
            ASSERT_LT(v.normal.y, -.9f) << "vertex " << i;
        }
    }
    // Overall most of the teapot faces away from its centre; what does not is
    // the inside of the rim, the underside of the knob and the sides of the
    // handle and spout that face the body (about 20%).
    size_t outward = 0;
    for (const MeshVertex& v : m.vertices) outward += glm::dot(v.normal, v.position - centroid) > 0.f;
    EXPECT_GT(outward, m.vertices.size() * 3 / 4);
    // The collapsed patch rows: lid tip straight up, bottom centre straight down.
    for (int p = teapot::kLid; p < teapot::kLid + 4; ++p)
        for (int i = 0; i <= n; ++i) {
            const MeshVertex& v = m.vertices[p * perPatch + i];
            test::expectVec3Near(v.position, {0.f, .825f, 0.f});
            EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
        }
    for (int p = teapot::kBottom; p < teapot::kBottom + 4; ++p)
        for (int i = 0; i <= n; ++i) EXPECT_EQ(m.vertices[p * perPatch + i].normal, glm::vec3(0, -1, 0));
}

TEST(Teapot, WindingMatchesNormalsAndOnlyCentreRowsDegenerate) {
    const int n = 10;
    const Mesh m = makeTeapot(1.f, n);
    size_t degenerate = 0, agree = 0, total = 0;
    for (size_t t = 0; t < m.indices.size() / 3; ++t) {
        const glm::vec3 g = test::geometricNormal(m, t);
        if (glm::length(g) < 1e-9f) {
            ++degenerate;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            ++total;
            agree += glm::dot(g, m.vertices[m.indices[t * 3 + k]].normal) > 0.f;
        }
    }
    // One triangle of each quad in the lid knob's and the bottom's first row.
    EXPECT_EQ(degenerate, 8u * n);
    EXPECT_EQ(agree, total);
}

// The patches meet without gaps: once coincident points are merged, the only
// open edges are the rim's inner edge and the lid's outer edge (the lid sits
// in the opening) and the two ends of the handle and of the spout (their
// ends dip into the body).
TEST(Teapot, PatchesMeetAlongTheirEdges) {
    for (int n : {3, 8}) {
        const Mesh m = makeTeapot(1.f, n);
        EXPECT_EQ(test::boundaryEdgeCount(m), 16 * n) << n;
    }
}

TEST(Teapot, Deterministic) {
    const Mesh a = makeTeapot(1.f, 5), b = makeTeapot(1.f, 5);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (size_t i = 0; i < a.vertices.size(); ++i) ASSERT_EQ(a.vertices[i].position, b.vertices[i].position);
    EXPECT_EQ(a.indices, b.indices);
}

}  // namespace
}  // namespace glimmer
