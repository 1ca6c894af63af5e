#include <cmath>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "mesh_checks.h"
#include "topology_checks.h"

namespace glimmer {
namespace {

// Every line joins two distinct positions and no two lines join the same pair.
void expectCleanWire(const Mesh& w) {
    ASSERT_EQ(w.primitive, Mesh::Primitive::Lines);
    ASSERT_EQ(w.indices.size() % 2, 0u);
    std::set<std::pair<test::PosKey, test::PosKey>> edges;
    for (size_t i = 0; i < w.indices.size(); i += 2) {
        ASSERT_LT(w.indices[i], w.vertices.size());
        ASSERT_LT(w.indices[i + 1], w.vertices.size());
        const auto a = test::posKey(w.vertices[w.indices[i]].position);
        const auto b = test::posKey(w.vertices[w.indices[i + 1]].position);
        ASSERT_NE(a, b) << "degenerate line " << i / 2;
        ASSERT_TRUE(edges.insert(std::minmax(a, b)).second) << "duplicate line " << i / 2;
    }
    // Every output vertex is used, each at its own position.
    std::set<std::uint32_t> used(w.indices.begin(), w.indices.end());
    EXPECT_EQ(used.size(), w.vertices.size());
    EXPECT_EQ(test::uniquePositionCount(w), w.vertices.size());
}

TEST(Wire, BoxHasTwelveEdgesAndSixDiagonals) {
    const Mesh w = makeWire(makeBox(2.f, 4.f, 6.f));
    expectCleanWire(w);
    EXPECT_EQ(w.vertices.size(), 8u);
    ASSERT_EQ(w.indices.size(), 18u * 2u);
    int edges = 0, diagonals = 0;
    for (size_t i = 0; i < w.indices.size(); i += 2) {
        const glm::vec3 d = glm::abs(w.vertices[w.indices[i]].position - w.vertices[w.indices[i + 1]].position);
        const int axes = (d.x > 0.f) + (d.y > 0.f) + (d.z > 0.f);
        edges += axes == 1;
        diagonals += axes == 2;
    }
    EXPECT_EQ(edges, 12);
    EXPECT_EQ(diagonals, 6);
    // Corner normals: the mean of the three faces meeting there.
    for (const MeshVertex& v : w.vertices)
        test::expectVec3Near(v.normal, glm::sign(v.position) / std::sqrt(3.f));
}

TEST(Wire, ClosedShapesFollowEuler) {
    // V - E + F = 2 after merging seams and poles.
    struct Case {
        const char* name;
        Mesh solid;
        size_t vertices, edges;
    };
    const Case cases[] = {
        {"sphere", makeSphere(1.f, 8, 4), 8 * 3 + 2, 8 * (3 * 4 - 3)},
        {"cylinder", makeCylinder(1.f, 1.f, 8), 2 * 8 + 2, 6 * 8},
        {"cone", makeCone(1.f, 1.f, 8), 8 + 2, 3 * 8},
        {"quadbox", makeQuadBox(1.f), 8, 18},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const Mesh w = makeWire(c.solid);
        expectCleanWire(w);
        EXPECT_EQ(w.vertices.size(), c.vertices);
        EXPECT_EQ(w.indices.size(), 2 * c.edges);
        EXPECT_EQ(long(w.vertices.size()) - long(c.edges) + long(c.solid.indices.size() / 3), 2);
    }
}

TEST(Wire, TorusAndGrids) {
    // Torus: genus 1, V - E + F = 0; rings*sides points, 3*rings*sides edges.
    const Mesh t = makeWire(makeTorus(1.f, .25f, 4, 6));
    expectCleanWire(t);
    EXPECT_EQ(t.vertices.size(), 24u);
    EXPECT_EQ(t.indices.size(), 2u * 72u);
    // A 3 x 2 quad grid: 9 + 8 grid lines and 6 diagonals.
    const Mesh q = makeWire(makeQuadXY(0.f, 1.f, 3, 2));
    expectCleanWire(q);
    EXPECT_EQ(q.vertices.size(), 12u);
    EXPECT_EQ(q.indices.size(), 2u * 23u);
    // Disk: 6 spokes and 6 rim edges.
    const Mesh d = makeWire(makeDiskXY(1.f, 6));
    EXPECT_EQ(d.indices.size(), 2u * 12u);
}

TEST(Wire, TeapotEdgesAreUniqueAndSkipDegenerates) {
    const Mesh solid = makeTeapot(1.f, 4);
    const Mesh w = makeWire(solid);
    expectCleanWire(w);
    EXPECT_EQ(w.indices.size() / 2, test::uniqueEdgeCount(solid));
    EXPECT_EQ(w.vertices.size(), test::uniquePositionCount(solid));
    test::expectFinite(w);
}

TEST(Wire, KeepsAttributesOfFirstVertex) {
    const Mesh solid = makeQuadXY(.5f, 1.f);
    const Mesh w = makeWire(solid);
    ASSERT_EQ(w.vertices.size(), 4u);
    EXPECT_TRUE(w.hasTangents);
    for (const MeshVertex& v : w.vertices) {
        EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
        EXPECT_EQ(v.tangent, glm::vec3(0, 1, 0));
        EXPECT_NEAR(v.st.s, (v.position.x + 1.f) / 2.f, 1e-6f);
    }
}

TEST(Wire, NonTrianglesGiveNothing) {
    Mesh pts = makePointCloud(10, 1.f, 1);
    const Mesh w = makeWire(pts);
    EXPECT_EQ(w.primitive, Mesh::Primitive::Lines);
    EXPECT_TRUE(w.indices.empty());
    EXPECT_TRUE(makeWire(Mesh{}).indices.empty());
}

// ---- adjacency ------------------------------------------------------------------

TEST(ObjAdjacency, TwoTriangleQuad) {
    const Mesh quad = makeQuadXY(0.f, 1.f);
    ASSERT_EQ(quad.indices, (std::vector<std::uint32_t>{0, 1, 3, 0, 3, 2}));
    const Mesh m = makeObjAdjacency(quad);
    EXPECT_EQ(m.primitive, Mesh::Primitive::TrianglesAdjacency);
    EXPECT_EQ(m.vertices.size(), 4u);
    // (0,1,3): 01 and 13 open (own opposite vertex), 30 borders (0,3,2) -> 2.
    // (0,3,2): 03 borders (0,1,3) -> 1, 32 and 20 open.
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 3, 1, 0, 3, 2, 0, 1, 3, 0, 2, 3}));
}

TEST(ObjAdjacency, ClosedTetrahedronFindsEveryNeighbour) {
    Mesh tet;
    for (glm::vec3 p : {glm::vec3(1, 1, 1), glm::vec3(1, -1, -1), glm::vec3(-1, 1, -1), glm::vec3(-1, -1, 1)}) {
        MeshVertex v;
        v.position = p;
        v.normal = glm::normalize(p);
        tet.vertices.push_back(v);
    }
    tet.indices = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2};
    test::expectClosedOriented(tet);
    const Mesh m = makeObjAdjacency(tet);
    ASSERT_EQ(m.indices.size(), 4u * 6u);
    for (size_t t = 0; t < 4; ++t) {
        const std::uint32_t a = tet.indices[t * 3], b = tet.indices[t * 3 + 1], c = tet.indices[t * 3 + 2];
        const std::uint32_t missing = 6 - a - b - c;  // the vertex not in this face
        EXPECT_EQ(m.indices[t * 6 + 0], a);
        EXPECT_EQ(m.indices[t * 6 + 2], b);
        EXPECT_EQ(m.indices[t * 6 + 4], c);
        for (int k : {1, 3, 5}) EXPECT_EQ(m.indices[t * 6 + k], missing) << "triangle " << t;
    }
}

// Split vertices (per-face normals) still connect: every edge of a box finds
// a neighbour whose far vertex lies off the edge and is not this triangle's
// own opposite corner.
TEST(ObjAdjacency, SplitVerticesConnectByPosition) {
    for (const Mesh& solid : {makeBox(), makeSphere(1.f, 6, 4)}) {
        const Mesh m = makeObjAdjacency(solid);
        ASSERT_EQ(m.indices.size(), solid.indices.size() * 2);
        EXPECT_EQ(m.vertices.size(), solid.vertices.size());
        for (size_t t = 0; t < solid.indices.size() / 3; ++t)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 a = solid.vertices[solid.indices[t * 3 + k]].position;
                const glm::vec3 b = solid.vertices[solid.indices[t * 3 + (k + 1) % 3]].position;
                const glm::vec3 own = solid.vertices[solid.indices[t * 3 + (k + 2) % 3]].position;
                ASSERT_EQ(m.indices[t * 6 + 2 * k], solid.indices[t * 3 + k]);
                const glm::vec3 adj = m.vertices[m.indices[t * 6 + 2 * k + 1]].position;
                ASSERT_GT(glm::length(adj - own), 1e-4f) << "triangle " << t << " edge " << k;
                ASSERT_GT(glm::length(adj - a), 1e-4f);
                ASSERT_GT(glm::length(adj - b), 1e-4f);
            }
    }
}

TEST(ObjAdjacency, NonTrianglesGiveNothing) {
    const Mesh m = makeObjAdjacency(makeWire(makeBox()));
    EXPECT_EQ(m.primitive, Mesh::Primitive::TrianglesAdjacency);
    EXPECT_TRUE(m.indices.empty());
}

}  // namespace
}  // namespace glimmer
