#include <cmath>
#include <set>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "mesh_checks.h"
#include "topology_checks.h"

namespace glimmer {
namespace {

using test::boundsOf;
using test::expectUnitNormals;
using test::expectVec3Near;
using test::expectWindingMatchesNormals;

float area(const Mesh& m) {
    float a = 0.f;
    for (size_t t = 0; t < m.indices.size() / 3; ++t) a += .5f * glm::length(test::geometricNormal(m, t));
    return a;
}

const float kPi = glm::pi<float>();

// ---- enum ---------------------------------------------------------------------

TEST(MeshPrimitive, ExistingValuesKept) {
    EXPECT_EQ(static_cast<int>(Mesh::Primitive::Triangles), 0);
    EXPECT_EQ(static_cast<int>(Mesh::Primitive::Lines), 1);
    EXPECT_EQ(static_cast<int>(Mesh::Primitive::Points), 2);
    EXPECT_NE(Mesh::Primitive::LinesAdjacency, Mesh::Primitive::TrianglesAdjacency);
    EXPECT_NE(Mesh::Primitive::Patches, Mesh::Primitive::Points);
}

// ---- cylinder -----------------------------------------------------------------

TEST(Cylinder, CountsBoundsAndClosedSurface) {
    const Mesh m = makeCylinder(2.f, 3.f, 8);
    EXPECT_EQ(m.vertices.size(), 2u * 9u + 2u * 9u);
    EXPECT_EQ(m.indices.size(), 4u * 8u * 3u);
    EXPECT_EQ(m.primitive, Mesh::Primitive::Triangles);
    EXPECT_FALSE(m.flat);
    EXPECT_TRUE(m.hasTangents);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, {-2.f, 0.f, -2.f});
    expectVec3Near(b.hi, {2.f, 3.f, 2.f});
    EXPECT_EQ(b.stLo, glm::vec2(0.f));
    EXPECT_EQ(b.stHi, glm::vec2(1.f));
    expectWindingMatchesNormals(m);
    expectUnitNormals(m);
    test::expectClosedOriented(m);
    // Octagonal prism: side 8 * chord * h, caps 2 * 8 triangles.
    const float chord = 2.f * 2.f * std::sin(kPi / 8.f);
    const float cap = 8.f * .5f * 4.f * std::sin(2.f * kPi / 8.f);
    EXPECT_NEAR(area(m), 8.f * chord * 3.f + 2.f * cap, 1e-3f);
}

TEST(Cylinder, SideAndCapAttributes) {
    const float r = 1.5f, h = 2.f;
    const Mesh m = makeCylinder(r, h, 12);
    int side = 0, top = 0, bottom = 0;
    for (const MeshVertex& v : m.vertices) {
        if (v.normal.y == 0.f) {  // side
            ++side;
            expectVec3Near(v.normal, glm::vec3(v.position.x, 0.f, v.position.z) / r);
            EXPECT_NEAR(v.st.t, v.position.y / h, 1e-6f);
            EXPECT_EQ(v.tangent, glm::vec3(0, 1, 0));
            // Longitude as the sphere: s = .5 faces +Z, s = .75 faces +X.
            const float lng = -kPi + 2.f * kPi * v.st.s;
            EXPECT_NEAR(v.position.x, r * std::sin(lng), 1e-5f);
            EXPECT_NEAR(v.position.z, r * std::cos(lng), 1e-5f);
        } else if (v.normal.y > 0.f) {
            ++top;
            EXPECT_FLOAT_EQ(v.position.y, h);
            EXPECT_NEAR(v.st.s, .5f + v.position.x / (2.f * r), 1e-6f);
            EXPECT_NEAR(v.st.t, .5f - v.position.z / (2.f * r), 1e-6f);
            EXPECT_EQ(v.tangent, glm::vec3(0, 0, -1));
        } else {
            ++bottom;
            EXPECT_FLOAT_EQ(v.position.y, 0.f);
            EXPECT_NEAR(v.st.s, .5f + v.position.x / (2.f * r), 1e-6f);
            EXPECT_NEAR(v.st.t, .5f + v.position.z / (2.f * r), 1e-6f);
            EXPECT_EQ(v.tangent, glm::vec3(0, 0, 1));
        }
    }
    EXPECT_EQ(side, 26);
    EXPECT_EQ(top, 13);
    EXPECT_EQ(bottom, 13);
}

TEST(Cylinder, DefaultsAndOddSlicesStillClosed) {
    const Mesh d = makeCylinder();
    EXPECT_EQ(d.indices.size(), 4u * 40u * 3u);
    const auto b = boundsOf(d);
    EXPECT_NEAR(b.hi.y, 1.f, 1e-6f);
    EXPECT_NEAR(b.hi.x, 1.f, 1e-5f);
    // Odd slice counts: cap rings must meet the side exactly.
    const Mesh m = makeCylinder(1.f, 1.f, 7);
    test::expectClosedOriented(m);
    // Fewer than 3 slices means 3.
    EXPECT_EQ(makeCylinder(1.f, 1.f, 1).indices.size(), 4u * 3u * 3u);
}

// ---- cone ---------------------------------------------------------------------

TEST(Cone, CountsBoundsAndClosedSurface) {
    const Mesh m = makeCone(1.f, 2.f, 8);
    EXPECT_EQ(m.vertices.size(), 9u + 8u + 9u);
    EXPECT_EQ(m.indices.size(), 2u * 8u * 3u);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, {-1.f, 0.f, -1.f});
    expectVec3Near(b.hi, {1.f, 2.f, 1.f});
    expectWindingMatchesNormals(m);
    expectUnitNormals(m);
    test::expectClosedOriented(m);
    EXPECT_EQ(test::uniquePositionCount(m), 8u + 2u);  // ring, apex, cap centre
}

TEST(Cone, SlantedNormalsAndTangents) {
    const float r = 1.f, h = 2.f;
    const Mesh m = makeCone(r, h, 16);
    int sideVertices = 0;
    for (const MeshVertex& v : m.vertices) {
        if (v.normal.y == -1.f) continue;  // bottom cap
        ++sideVertices;
        // The slant: normal . (apex - base point on its meridian) == 0, and
        // the normal leans up by atan(r / h).
        EXPECT_NEAR(v.normal.y, r / std::sqrt(r * r + h * h), 1e-5f);
        EXPECT_NEAR(glm::dot(v.normal, v.tangent), 0.f, 1e-5f);
        EXPECT_NEAR(glm::length(v.tangent), 1.f, 1e-5f);
        EXPECT_GT(v.tangent.y, 0.f);  // towards the apex
        const float lng = -kPi + 2.f * kPi * v.st.s;
        const glm::vec3 radial{std::sin(lng), 0.f, std::cos(lng)};
        const glm::vec3 slantLine = glm::vec3(0.f, h, 0.f) - r * radial;
        EXPECT_NEAR(glm::dot(v.normal, slantLine), 0.f, 1e-5f);
        EXPECT_GT(glm::dot(v.normal, radial), 0.f);
        if (v.st.t == 1.f) expectVec3Near(v.position, {0.f, h, 0.f}, 0.f);
        else EXPECT_NEAR(v.st.t, v.position.y / h, 1e-6f);
    }
    EXPECT_EQ(sideVertices, 17 + 16);
}

// ---- disk ---------------------------------------------------------------------

TEST(DiskXY, CountsNormalsAndTextureCoordinates) {
    const Mesh m = makeDiskXY(2.f, 6);
    EXPECT_EQ(m.vertices.size(), 7u);
    EXPECT_EQ(m.indices.size(), 18u);
    EXPECT_TRUE(m.flat);
    for (const MeshVertex& v : m.vertices) {
        EXPECT_EQ(v.position.z, 0.f);
        EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
        EXPECT_NEAR(v.st.s, .5f + v.position.x / 4.f, 1e-6f);
        EXPECT_NEAR(v.st.t, .5f + v.position.y / 4.f, 1e-6f);
        EXPECT_NEAR(glm::length(v.position), &v == &m.vertices[0] ? 0.f : 2.f, 1e-5f);
    }
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 6.f * .5f * 4.f * std::sin(2.f * kPi / 6.f), 1e-4f);
    EXPECT_EQ(test::boundaryEdgeCount(m), 6);
    const Mesh d = makeDiskXY();
    EXPECT_EQ(d.indices.size(), 40u * 3u);
    EXPECT_NEAR(boundsOf(d).hi.x, 1.f, 1e-6f);
}

// ---- quad box -------------------------------------------------------------------

TEST(QuadBox, SixInwardFaces) {
    const Mesh m = makeQuadBox(3.f);
    EXPECT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.indices.size(), 36u);
    EXPECT_FALSE(m.flat);
    const auto b = boundsOf(m);
    expectVec3Near(b.lo, glm::vec3(-3.f));
    expectVec3Near(b.hi, glm::vec3(3.f));
    EXPECT_EQ(b.stLo, glm::vec2(0.f));
    EXPECT_EQ(b.stHi, glm::vec2(1.f));
    std::set<std::tuple<float, float, float>> normals;
    for (const MeshVertex& v : m.vertices) {
        EXPECT_LT(glm::dot(v.normal, v.position), 0.f);  // towards the centre
        EXPECT_FLOAT_EQ(glm::dot(v.normal, v.position), -3.f);  // on its wall
        EXPECT_EQ(glm::dot(v.normal, v.tangent), 0.f);
        normals.insert({v.normal.x, v.normal.y, v.normal.z});
    }
    EXPECT_EQ(normals.size(), 6u);
    expectWindingMatchesNormals(m);  // counter-clockwise seen from inside
    test::expectClosedOriented(m);
    EXPECT_NEAR(area(m), 6.f * 36.f, 1e-3f);
}

TEST(QuadBox, TextureRightAndUpSeenFromInside) {
    const Mesh m = makeQuadBox(1.f);
    for (size_t f = 0; f < 6; ++f) {
        const MeshVertex* v = &m.vertices[f * 4];
        // Find the corners at st (0,0), (1,0), (0,1).
        glm::vec3 p00{0.f}, p10{0.f}, p01{0.f};
        for (int k = 0; k < 4; ++k) {
            if (v[k].st == glm::vec2(0, 0)) p00 = v[k].position;
            if (v[k].st == glm::vec2(1, 0)) p10 = v[k].position;
            if (v[k].st == glm::vec2(0, 1)) p01 = v[k].position;
        }
        const glm::vec3 sDir = (p10 - p00) / 2.f, tDir = (p01 - p00) / 2.f;
        const glm::vec3 look = -v[0].normal;  // from the centre towards the wall
        // s to the right of t (up) for a viewer looking at the wall.
        expectVec3Near(glm::cross(look, tDir), sDir);
        expectVec3Near(v[0].tangent, tDir);
        if (std::abs(look.y) < .5f) expectVec3Near(tDir, {0, 1, 0});
    }
}

// ---- point clouds ---------------------------------------------------------------

TEST(PointCloud, CountBoundsAndSpread) {
    const Mesh m = makePointCloud(8000, 2.f, 7);
    EXPECT_EQ(m.primitive, Mesh::Primitive::Points);
    ASSERT_EQ(m.vertices.size(), 8000u);
    ASSERT_EQ(m.indices.size(), 8000u);
    int octant[8] = {};
    glm::vec3 mean{0.f};
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        EXPECT_EQ(m.indices[i], i);
        const glm::vec3 p = m.vertices[i].position;
        ASSERT_LE(glm::abs(p).x, 2.f);
        ASSERT_LE(glm::abs(p).y, 2.f);
        ASSERT_LE(glm::abs(p).z, 2.f);
        EXPECT_NEAR(m.vertices[i].st.s, p.x / 4.f + .5f, 1e-6f);
        EXPECT_NEAR(m.vertices[i].st.t, p.y / 4.f + .5f, 1e-6f);
        ++octant[(p.x > 0) + 2 * (p.y > 0) + 4 * (p.z > 0)];
        mean += p / 8000.f;
    }
    for (int o : octant) {
        EXPECT_GT(o, 850);
        EXPECT_LT(o, 1150);
    }
    EXPECT_LT(glm::length(mean), .1f);
    // It fills the cube rather than a smaller one.
    const auto b = boundsOf(m);
    EXPECT_LT(b.lo.x, -1.95f);
    EXPECT_GT(b.hi.z, 1.95f);
}

TEST(PointCloud, Deterministic) {
    const Mesh a = makePointCloud(100, 1.f, 3), b = makePointCloud(100, 1.f, 3);
    const Mesh c = makePointCloud(100, 1.f, 4);
    int same = 0;
    for (size_t i = 0; i < 100; ++i) {
        EXPECT_EQ(a.vertices[i].position, b.vertices[i].position);
        same += a.vertices[i].position == c.vertices[i].position;
    }
    EXPECT_EQ(same, 0);
    // Points differ from each other (the generator advances).
    std::set<float> xs;
    for (const MeshVertex& v : a.vertices) xs.insert(v.position.x);
    EXPECT_EQ(xs.size(), 100u);
    EXPECT_TRUE(makePointCloud(0, 1.f, 1).vertices.empty());
    EXPECT_TRUE(makePointCloud(-5, 1.f, 1).vertices.empty());
}

TEST(JitterCloud, ZeroJitterIsTheGrid) {
    const Mesh m = makeJitterCloud(4, 2.f, 0.f, 9);
    EXPECT_EQ(m.primitive, Mesh::Primitive::Points);
    ASSERT_EQ(m.vertices.size(), 64u);
    ASSERT_EQ(m.indices.size(), 64u);
    // Cell edge 1, centres at -1.5, -.5, .5, 1.5; x fastest.
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                expectVec3Near(m.vertices[(k * 4 + j) * 4 + i].position,
                               {-1.5f + i, -1.5f + j, -1.5f + k}, 1e-6f);
}

TEST(JitterCloud, JitterStaysInItsCellAndIsDeterministic) {
    const int n = 5;
    const float size = 1.f, cell = 2.f * size / n;
    const Mesh m = makeJitterCloud(n, size, .5f, 11);
    const Mesh again = makeJitterCloud(n, size, .5f, 11);
    const Mesh other = makeJitterCloud(n, size, .5f, 12);
    ASSERT_EQ(m.vertices.size(), 125u);
    float largest = 0.f;
    int differs = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const size_t idx = (k * n + j) * n + i;
                const glm::vec3 centre = glm::vec3(-size) + cell * (glm::vec3(i, j, k) + .5f);
                const glm::vec3 d = glm::abs(m.vertices[idx].position - centre);
                largest = std::max({largest, d.x, d.y, d.z});
                EXPECT_LE(std::max({d.x, d.y, d.z}), .25f * cell + 1e-6f);
                EXPECT_EQ(m.vertices[idx].position, again.vertices[idx].position);
                differs += m.vertices[idx].position != other.vertices[idx].position;
            }
    EXPECT_GT(largest, .2f * cell);  // it did move them, by up to a quarter cell
    EXPECT_EQ(differs, 125);
    // Full jitter still keeps every point inside the cube.
    const auto b = boundsOf(makeJitterCloud(6, 1.f, 5.f, 1));
    EXPECT_GE(b.lo.x, -1.f);
    EXPECT_LE(b.hi.y, 1.f);
    EXPECT_GT(b.hi.z, .9f);
}

// ---- Triangles / LinesAdjacency --------------------------------------------------

TEST(TrianglesFrom, OneTriangleFaceNormal) {
    const Mesh m = makeTrianglesFrom({{0, 0, 0}, {0, 2, 0}, {0, 0, 2}});
    ASSERT_EQ(m.vertices.size(), 3u);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_TRUE(m.flat);
    for (const MeshVertex& v : m.vertices) {
        EXPECT_EQ(v.normal, glm::vec3(1, 0, 0));  // (0,2,0) x (0,0,2)
        expectVec3Near(v.tangent, {0, 0, 1});
    }
    EXPECT_EQ(m.vertices[1].st, glm::vec2(1, 0));
    EXPECT_EQ(m.vertices[2].st, glm::vec2(0, 1));
    expectWindingMatchesNormals(m);
    EXPECT_NEAR(area(m), 2.f, 1e-6f);
}

TEST(TrianglesFrom, SeveralTrianglesEachWithItsOwnNormal) {
    // Two triangles of a tent plus a stray point that is ignored.
    const Mesh m = makeTrianglesFrom(
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 1}, {1, 0, 0}, {0, 0, 0}, {0, 1, -1}, {5, 5, 5}});
    ASSERT_EQ(m.vertices.size(), 6u);
    ASSERT_EQ(m.indices.size(), 6u);
    EXPECT_FALSE(m.flat);
    expectWindingMatchesNormals(m);
    expectUnitNormals(m);
    expectVec3Near(m.vertices[0].normal, glm::normalize(glm::vec3(0, -1, 1)));
    expectVec3Near(m.vertices[3].normal, glm::normalize(glm::vec3(0, -1, -1)));
    // Degenerate: +Z, nothing non-finite.
    const Mesh d = makeTrianglesFrom({{1, 1, 1}, {2, 2, 2}, {3, 3, 3}});
    EXPECT_EQ(d.vertices[0].normal, glm::vec3(0, 0, 1));
    EXPECT_TRUE(makeTrianglesFrom({{0, 0, 0}, {1, 0, 0}}).indices.empty());
}

TEST(LinesAdjacency, FourPointsPerLine) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 0, 0}, {4, 4, 4},
                                      {5, 5, 5}, {6, 6, 6}, {7, 7, 7}, {8, 8, 8}};
    const Mesh m = makeLinesAdjacency(p);
    EXPECT_EQ(m.primitive, Mesh::Primitive::LinesAdjacency);
    ASSERT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    for (size_t i = 0; i < 8; ++i) {
        EXPECT_EQ(m.vertices[i].position, p[i]);
        EXPECT_FLOAT_EQ(m.vertices[i].st.s, float(i % 4) / 3.f);
    }
    EXPECT_TRUE(makeLinesAdjacency({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).indices.empty());
}

// ---- glBegin / glEnd -------------------------------------------------------------

TEST(Immediate, ParsesGlNames) {
    using P = ImmediatePrimitive;
    EXPECT_EQ(parseImmediatePrimitive("points"), P::Points);
    EXPECT_EQ(parseImmediatePrimitive("GL_LINES"), P::Lines);
    EXPECT_EQ(parseImmediatePrimitive("line_strip"), P::LineStrip);
    EXPECT_EQ(parseImmediatePrimitive("Line_Loop"), P::LineLoop);
    EXPECT_EQ(parseImmediatePrimitive("triangles"), P::Triangles);
    EXPECT_EQ(parseImmediatePrimitive("GL_TRIANGLE_STRIP"), P::TriangleStrip);
    EXPECT_EQ(parseImmediatePrimitive("triangle_fan"), P::TriangleFan);
    EXPECT_EQ(parseImmediatePrimitive("QUADS"), P::Quads);
    EXPECT_EQ(parseImmediatePrimitive("quad_strip"), P::QuadStrip);
    EXPECT_EQ(parseImmediatePrimitive("polygon"), P::Polygon);
    EXPECT_EQ(parseImmediatePrimitive("gl_patches"), P::Patches);
    EXPECT_FALSE(parseImmediatePrimitive("triangle"));
    EXPECT_FALSE(parseImmediatePrimitive("quadstrip"));
    EXPECT_FALSE(parseImmediatePrimitive(""));
    EXPECT_FALSE(parseImmediatePrimitive("GL_"));
}

TEST(Immediate, PointsAndPatchesKeepOrder) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {1, 1, 1}};
    const Mesh pts = makeImmediate(ImmediatePrimitive::Points, p);
    EXPECT_EQ(pts.primitive, Mesh::Primitive::Points);
    EXPECT_EQ(pts.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
    const Mesh pat = makeImmediate(ImmediatePrimitive::Patches, p);
    EXPECT_EQ(pat.primitive, Mesh::Primitive::Patches);
    EXPECT_EQ(pat.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
    ASSERT_EQ(pat.vertices.size(), 5u);
    for (size_t i = 0; i < p.size(); ++i) EXPECT_EQ(pat.vertices[i].position, p[i]);
}

TEST(Immediate, LineKinds) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 2, 0}};
    const Mesh lines = makeImmediate(ImmediatePrimitive::Lines, p);
    EXPECT_EQ(lines.primitive, Mesh::Primitive::Lines);
    EXPECT_EQ(lines.indices, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    const Mesh strip = makeImmediate(ImmediatePrimitive::LineStrip, p);
    EXPECT_EQ(strip.primitive, Mesh::Primitive::Lines);
    EXPECT_EQ(strip.indices, (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 4}));
    const Mesh loop = makeImmediate(ImmediatePrimitive::LineLoop, p);
    EXPECT_EQ(loop.indices, (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 4, 4, 0}));
    EXPECT_TRUE(makeImmediate(ImmediatePrimitive::LineStrip, {{0, 0, 0}}).indices.empty());
}

// A planar zig-zag in z = 0, all of whose GL triangles face +Z.
std::vector<glm::vec3> zigzag(int n) {
    std::vector<glm::vec3> p;
    for (int i = 0; i < n; ++i) p.push_back({float(i / 2), float(i % 2), 0.f});
    return p;
}

TEST(Immediate, TriangleStripAlternatesLikeGl) {
    // Even points on the top row, odd ones below: (0,1,2) is counter-clockwise
    // from +Z, and GL's odd triangles (2,1,3), (4,3,5) keep that facing.
    std::vector<glm::vec3> p = zigzag(6);
    for (glm::vec3& q : p) q.y = 1.f - q.y;
    const Mesh m = makeImmediate(ImmediatePrimitive::TriangleStrip, p);
    ASSERT_EQ(m.indices.size(), 4u * 3u);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5}));
    expectWindingMatchesNormals(m);
    for (const MeshVertex& v : m.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    EXPECT_TRUE(m.flat);
    EXPECT_NEAR(area(m), 2.f, 1e-6f);
}

TEST(Immediate, TrianglesFansPolygons) {
    const Mesh t = makeImmediate(ImmediatePrimitive::Triangles,
                                 {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {9, 9, 9}});
    EXPECT_EQ(t.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_FALSE(t.flat);  // two planes... parallel but apart, so one can hide the other
    expectWindingMatchesNormals(t);
    // A regular pentagon as a fan and as a polygon: 3 triangles, its area.
    std::vector<glm::vec3> pent;
    for (int i = 0; i < 5; ++i) {
        const float a = 2.f * kPi * i / 5.f;
        pent.push_back({std::cos(a), std::sin(a), 0.f});
    }
    const float pentArea = 5.f * .5f * std::sin(2.f * kPi / 5.f);
    for (auto prim : {ImmediatePrimitive::TriangleFan, ImmediatePrimitive::Polygon}) {
        const Mesh m = makeImmediate(prim, pent);
        EXPECT_EQ(m.primitive, Mesh::Primitive::Triangles);
        EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
        expectWindingMatchesNormals(m);
        EXPECT_TRUE(m.flat);
        EXPECT_NEAR(area(m), pentArea, 1e-5f);
    }
    // Clockwise polygon: faces -Z.
    std::vector<glm::vec3> cw(pent.rbegin(), pent.rend());
    const Mesh m = makeImmediate(ImmediatePrimitive::Polygon, cw);
    for (const MeshVertex& v : m.vertices) expectVec3Near(v.normal, {0, 0, -1});
    expectWindingMatchesNormals(m);
}

TEST(Immediate, QuadsAndQuadStrip) {
    // Two unit quads side by side, counter-clockwise from +Z.
    const Mesh q = makeImmediate(ImmediatePrimitive::Quads, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                              {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0},
                                                              {5, 5, 5}, {6, 6, 6}});
    EXPECT_EQ(q.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}));
    expectWindingMatchesNormals(q);
    EXPECT_NEAR(area(q), 2.f, 1e-6f);
    EXPECT_TRUE(q.flat);
    // Quad strip: pairs (bottom, top) left to right; GL quad k is 2k, 2k+1, 2k+3, 2k+2.
    const Mesh s = makeImmediate(ImmediatePrimitive::QuadStrip,
                                 {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}, {3, 0, 0}});
    ASSERT_EQ(s.indices.size(), 2u * 2u * 3u);
    EXPECT_NEAR(area(s), 2.f, 1e-6f);
    expectWindingMatchesNormals(s);  // (0,0),(0,1),(1,1): clockwise from +Z, so faces -Z
    for (std::uint32_t i : s.indices) EXPECT_LT(i, 6u);
    for (size_t i = 0; i < 6; ++i) expectVec3Near(s.vertices[i].normal, {0, 0, -1});
}

TEST(Immediate, BentStripGetsSmoothNormals) {
    // A strip folded along x = 1: shared vertices sum their triangles' area
    // weighted face normals (vertex 2: one triangle of the flat quad, two of
    // the bent one).
    const Mesh m = makeImmediate(ImmediatePrimitive::QuadStrip,
                                 {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 1}, {2, 1, 1}});
    EXPECT_FALSE(m.flat);
    expectUnitNormals(m);
    expectVec3Near(m.vertices[0].normal, {0, 0, -1});
    expectVec3Near(m.vertices[2].normal, glm::normalize(glm::vec3(2, 0, -3)));
    expectVec3Near(m.vertices[4].normal, glm::normalize(glm::vec3(1, 0, -1)));
}

}  // namespace
}  // namespace glimmer
