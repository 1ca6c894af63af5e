#include "geometry/mesh.h"
#include "geometry/mesh_builder.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace glimmer {

namespace {

// Triangles for a (cols+1) x (rows+1) vertex grid stored row by row, where
// going right then up is counter-clockwise seen from the front.
void gridIndices(Mesh& m, int cols, int rows, bool flip = false) {
    const auto stride = static_cast<std::uint32_t>(cols + 1);
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            const std::uint32_t a = j * stride + i, b = a + 1, c = b + stride, d = a + stride;
            if (flip)
                m.indices.insert(m.indices.end(), {a, d, c, a, c, b});
            else
                m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
    }
}

// A square of half-extent `size` around `center`, s running along sAxis and
// t along tAxis.
Mesh makeQuad(glm::vec3 center, glm::vec3 sAxis, glm::vec3 tAxis, glm::vec3 normal, float size,
              int ns, int nt) {
    ns = std::max(ns, 1);
    nt = std::max(nt, 1);
    Mesh m;
    m.flat = true;
    m.hasTangents = true;
    m.vertices.reserve(static_cast<size_t>(ns + 1) * (nt + 1));
    for (int j = 0; j <= nt; ++j) {
        for (int i = 0; i <= ns; ++i) {
            const float s = float(i) / float(ns), t = float(j) / float(nt);
            MeshVertex v;
            v.position = center + (2.f * s - 1.f) * size * sAxis + (2.f * t - 1.f) * size * tAxis;
            v.normal = normal;
            v.st = {s, t};
            v.tangent = tAxis;
            m.vertices.push_back(v);
        }
    }
    // When (s, t) is a left-handed frame seen from the normal's side, the
    // grid's natural order would face away.
    gridIndices(m, ns, nt, glm::dot(glm::cross(sAxis, tAxis), normal) < 0.f);
    return m;
}

}  // namespace

Mesh makeQuadXY(float z, float size, int nx, int ny) {
    return makeQuad({0.f, 0.f, z}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}, size, nx, ny);
}

Mesh makeQuadXZ(float y, float size, int nx, int nz) {
    return makeQuad({0.f, y, 0.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}, size, nx, nz);
}

Mesh makeQuadYZ(float x, float size, int ny, int nz) {
    return makeQuad({x, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}, {1.f, 0.f, 0.f}, size, ny, nz);
}

Mesh makeSphere(float radius, int slices, int stacks) {
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    const float pi = glm::pi<float>();
    Mesh m;
    m.hasTangents = true;
    m.vertices.reserve(static_cast<size_t>(slices + 1) * (stacks + 1));
    for (int j = 0; j <= stacks; ++j) {
        const float t = float(j) / float(stacks);
        const float lat = -pi / 2.f + pi * t;
        // Exact poles: cos(pi/2) in float is not 0, and the pole rows must
        // collapse to a single point for the fan triangles to be clean.
        const float cl = (j == 0 || j == stacks) ? 0.f : std::cos(lat);
        const float sl = j == 0 ? -1.f : j == stacks ? 1.f : std::sin(lat);
        for (int i = 0; i <= slices; ++i) {
            const float s = float(i) / float(slices);
            // Seam at -Z so that s = .5 faces a viewer on +Z (OsuSphere's layout).
            const float lng = -pi + 2.f * pi * s;
            const float sn = std::sin(lng), cn = std::cos(lng);
            MeshVertex v;
            v.normal = {cl * sn, sl, cl * cn};
            v.position = radius * v.normal;
            v.st = {s, t};
            // d normal / d lat; at a pole this is the limit along the vertex's
            // own meridian, so it is still unit, tangent to the sphere and
            // continuous within each column.
            v.tangent = {-sl * sn, cl, -sl * cn};
            m.vertices.push_back(v);
        }
    }
    const auto stride = static_cast<std::uint32_t>(slices + 1);
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            const std::uint32_t a = j * stride + i, b = a + 1, c = b + stride, d = a + stride;
            // Skip the triangle that would be degenerate on a pole row.
            if (j != 0) m.indices.insert(m.indices.end(), {a, b, c});
            if (j != stacks - 1) m.indices.insert(m.indices.end(), {a, c, d});
        }
    }
    return m;
}

Mesh makeTorus(float outer, float inner, int sides, int rings) {
    sides = std::max(sides, 3);
    rings = std::max(rings, 3);
    const float twoPi = glm::two_pi<float>();
    Mesh m;
    m.hasTangents = true;
    m.vertices.reserve(static_cast<size_t>(rings + 1) * (sides + 1));
    for (int j = 0; j <= sides; ++j) {
        const float t = float(j) / float(sides);
        const float v = twoPi * t;
        const float cv = std::cos(v), sv = std::sin(v);
        for (int i = 0; i <= rings; ++i) {
            const float s = float(i) / float(rings);
            const float u = twoPi * s;
            const float cu = std::cos(u), su = std::sin(u);
            MeshVertex vx;
            vx.normal = {cv * cu, cv * su, sv};
            vx.position = glm::vec3(outer * cu, outer * su, 0.f) + inner * vx.normal;
            vx.st = {s, t};
            vx.tangent = {-sv * cu, -sv * su, cv};  // d position / d t, around the tube
            m.vertices.push_back(vx);
        }
    }
    // d/ds x d/dt points along the outward normal, so the plain grid order is
    // counter-clockwise from outside.
    gridIndices(m, rings, sides);
    return m;
}

void appendQuadFace(Mesh& m, glm::vec3 centre, glm::vec3 sHalf, glm::vec3 tHalf, glm::vec3 normal, glm::vec3 tangent) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (int k = 0; k < 4; ++k) {
        const float s = (k == 1 || k == 2) ? 1.f : 0.f;
        const float t = k >= 2 ? 1.f : 0.f;
        MeshVertex v;
        v.position = centre + (2.f * s - 1.f) * sHalf + (2.f * t - 1.f) * tHalf;
        v.normal = normal;
        v.st = {s, t};
        v.tangent = tangent;
        m.vertices.push_back(v);
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

Mesh makeBox(float dx, float dy, float dz) {
    const glm::vec3 h{dx / 2.f, dy / 2.f, dz / 2.f};
    struct Face {
        glm::vec3 n, s, t;  // s x t == n, so s-then-t order is CCW from outside
    };
    // Laid out like an unfolded cube map: t is up on the side faces.
    static const Face faces[] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    Mesh m;
    m.hasTangents = true;
    m.vertices.reserve(24);
    m.indices.reserve(36);
    for (const Face& f : faces) appendQuadFace(m, h * f.n, h * f.s, h * f.t, f.n, f.t);
    return m;
}

}  // namespace glimmer
