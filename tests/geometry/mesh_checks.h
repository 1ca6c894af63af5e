// Checks shared by the shape and OBJ tests.
#pragma once
#include <cmath>

#include <gtest/gtest.h>

#include "geometry/mesh.h"

namespace glimmer::test {

inline glm::vec3 geometricNormal(const Mesh& m, size_t tri) {
    const glm::vec3 a = m.vertices[m.indices[tri * 3]].position;
    const glm::vec3 b = m.vertices[m.indices[tri * 3 + 1]].position;
    const glm::vec3 c = m.vertices[m.indices[tri * 3 + 2]].position;
    return glm::cross(b - a, c - a);
}

// Indices in range, no degenerate triangles, and every triangle wound
// counter-clockwise as seen from the side its stored normals point to.
inline void expectWindingMatchesNormals(const Mesh& m) {
    ASSERT_EQ(m.primitive, Mesh::Primitive::Triangles);
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
    for (size_t t = 0; t < m.indices.size() / 3; ++t) {
        const glm::vec3 g = geometricNormal(m, t);
        ASSERT_GT(glm::length(g), 0.f) << "degenerate triangle " << t;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = m.vertices[m.indices[t * 3 + k]].normal;
            ASSERT_GT(glm::dot(g, n), 0.f) << "triangle " << t << " corner " << k;
        }
    }
}

inline void expectUnitNormals(const Mesh& m) {
    for (size_t i = 0; i < m.vertices.size(); ++i)
        ASSERT_NEAR(glm::length(m.vertices[i].normal), 1.f, 1e-5f) << "vertex " << i;
}

struct Bounds {
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    glm::vec2 stLo{INFINITY}, stHi{-INFINITY};
};

inline Bounds boundsOf(const Mesh& m) {
    Bounds b;
    for (const MeshVertex& v : m.vertices) {
        b.lo = glm::min(b.lo, v.position);
        b.hi = glm::max(b.hi, v.position);
        b.stLo = glm::min(b.stLo, v.st);
        b.stHi = glm::max(b.stHi, v.st);
    }
    return b;
}

inline void expectVec3Near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace glimmer::test
