// Cylinder, cone, disk, skybox cube, point clouds and meshes from points
// given in the script (Triangles, LinesAdjacency, glBegin/glEnd).
#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "geometry/mesh.h"
#include "geometry/planarity.h"
#include "geometry/mesh_builder.h"
#include "util/pcg32.h"

namespace glimmer {

namespace {

// Longitude of s, as makeSphere: -pi at s = 0, the seam facing -Z.
float longitude(float s) { return -glm::pi<float>() + glm::two_pi<float>() * s; }

// A flat disk cap around (0, y, 0) with normal +Y (up) or -Y, appended to m:
// centre vertex then a ring of `slices` vertices.
void addCap(Mesh& m, float radius, float y, int slices, bool up) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    const glm::vec3 n{0.f, up ? 1.f : -1.f, 0.f};
    const glm::vec3 tan{0.f, 0.f, up ? -1.f : 1.f};
    MeshVertex c;
    c.position = {0.f, y, 0.f};
    c.normal = n;
    c.st = {.5f, .5f};
    c.tangent = tan;
    m.vertices.push_back(c);
    for (int i = 0; i < slices; ++i) {
        // The same longitudes (and so the same floats) as the side's columns.
        const float a = longitude(float(i) / float(slices));
        const float x = std::sin(a), z = std::cos(a);
        MeshVertex v;
        v.position = {radius * x, y, radius * z};
        v.normal = n;
        v.st = {.5f + .5f * x, up ? .5f - .5f * z : .5f + .5f * z};
        v.tangent = tan;
        m.vertices.push_back(v);
    }
    // Longitude grows from -Z towards -X: counter-clockwise seen from +Y.
    for (int i = 0; i < slices; ++i) {
        const std::uint32_t a = base + 1 + i, b = base + 1 + (i + 1) % slices;
        if (up)
            m.indices.insert(m.indices.end(), {base, a, b});
        else
            m.indices.insert(m.indices.end(), {base, b, a});
    }
}

// Everything the triangles touch in one plane (geometry/planarity.h)?
bool planar(const Mesh& m) {
    std::vector<glm::dvec3> points;
    points.reserve(m.indices.size());
    for (std::uint32_t i : m.indices) points.emplace_back(m.vertices[i].position);
    return coplanar(points);
}

Mesh pointsMesh(const std::vector<glm::vec3>& positions, float size) {
    Mesh m;
    m.primitive = Mesh::Primitive::Points;
    m.vertices.reserve(positions.size());
    m.indices.reserve(positions.size());
    for (const glm::vec3& p : positions) {
        MeshVertex v;
        v.position = p;
        v.st = size > 0.f ? glm::vec2(p.x, p.y) / (2.f * size) + .5f : glm::vec2(.5f);
        m.indices.push_back(static_cast<std::uint32_t>(m.vertices.size()));
        m.vertices.push_back(v);
    }
    return m;
}

glm::vec3 faceNormal(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 g = glm::cross(b - a, c - a);
    const float len = glm::length(g);
    return len > 0.f && std::isfinite(len) ? g / len : glm::vec3(0.f, 0.f, 1.f);
}

}  // namespace

Mesh makeCylinder(float radius, float height, int slices) {
    slices = std::max(slices, 3);
    Mesh m;
    m.hasTangents = true;
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= slices; ++i) {
            const float s = float(i) / float(slices);
            const float lng = longitude(s);
            MeshVertex v;
            v.normal = {std::sin(lng), 0.f, std::cos(lng)};
            v.position = glm::vec3(radius * v.normal.x, float(j) * height, radius * v.normal.z);
            v.st = {s, float(j)};
            v.tangent = {0.f, 1.f, 0.f};
            m.vertices.push_back(v);
        }
    }
    // d/ds x d/dt points outward, so s-then-t is counter-clockwise from outside.
    const auto stride = static_cast<std::uint32_t>(slices + 1);
    for (std::uint32_t i = 0; i < std::uint32_t(slices); ++i) {
        const std::uint32_t a = i, b = i + 1, c = b + stride, d = a + stride;
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
    addCap(m, radius, 0.f, slices, false);
    addCap(m, radius, height, slices, true);
    return m;
}

Mesh makeCone(float radius, float height, int slices) {
    slices = std::max(slices, 3);
    Mesh m;
    m.hasTangents = true;
    const float slant = std::sqrt(height * height + radius * radius);
    auto sideVertex = [&](float s, float t) {
        const float lng = longitude(s);
        const float sn = std::sin(lng), cn = std::cos(lng);
        MeshVertex v;
        v.position = {(1.f - t) * radius * sn, t * height, (1.f - t) * radius * cn};
        v.normal = slant > 0.f ? glm::vec3(height * sn, radius, height * cn) / slant
                               : glm::vec3(0.f, 1.f, 0.f);
        v.st = {s, t};
        v.tangent = slant > 0.f ? glm::vec3(-radius * sn, height, -radius * cn) / slant
                                : glm::vec3(0.f, 1.f, 0.f);
        return v;
    };
    for (int i = 0; i <= slices; ++i) m.vertices.push_back(sideVertex(float(i) / float(slices), 0.f));
    const auto apex0 = static_cast<std::uint32_t>(m.vertices.size());
    for (int i = 0; i < slices; ++i)
        m.vertices.push_back(sideVertex((float(i) + .5f) / float(slices), 1.f));
    // Exactly one apex point, whatever sin/cos round to.
    for (std::uint32_t i = apex0; i < m.vertices.size(); ++i) m.vertices[i].position = {0.f, height, 0.f};
    for (std::uint32_t i = 0; i < std::uint32_t(slices); ++i)
        m.indices.insert(m.indices.end(), {i, i + 1, apex0 + i});
    addCap(m, radius, 0.f, slices, false);
    return m;
}

Mesh makeDiskXY(float radius, int slices) {
    slices = std::max(slices, 3);
    const float twoPi = glm::two_pi<float>();
    Mesh m;
    m.flat = true;
    m.hasTangents = true;
    MeshVertex c;
    c.normal = {0.f, 0.f, 1.f};
    c.st = {.5f, .5f};
    m.vertices.push_back(c);
    for (int i = 0; i < slices; ++i) {
        const float a = twoPi * float(i) / float(slices);
        const float x = std::cos(a), y = std::sin(a);
        MeshVertex v;
        v.position = {radius * x, radius * y, 0.f};
        v.st = {.5f + .5f * x, .5f + .5f * y};
        m.vertices.push_back(v);
    }
    // Ring from +X towards +Y: counter-clockwise seen from +Z.
    for (std::uint32_t i = 0; i < std::uint32_t(slices); ++i)
        m.indices.insert(m.indices.end(), {0u, 1 + i, 1 + (i + 1) % std::uint32_t(slices)});
    return m;
}

Mesh makeQuadBox(float size) {
    struct Face {
        glm::vec3 n, s, t;  // n is inward; s x t == n, so s-then-t is CCW from inside
    };
    static const Face faces[] = {
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   // wall at +X
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},   // wall at -X
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},  // wall at +Z
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},    // wall at -Z
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},   // ceiling at +Y
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},   // floor at -Y
    };
    Mesh m;
    m.hasTangents = true;
    for (const Face& f : faces) appendQuadFace(m, -size * f.n, size * f.s, size * f.t, f.n, f.t);
    return m;
}

Mesh makePointCloud(int count, float size, std::uint32_t seed) {
    Pcg32 rng(seed);
    std::vector<glm::vec3> p(static_cast<size_t>(std::max(count, 0)));
    for (glm::vec3& q : p) {
        const float x = rng.symmetric(), y = rng.symmetric(), z = rng.symmetric();
        q = size * glm::vec3(x, y, z);
    }
    return pointsMesh(p, size);
}

Mesh makeJitterCloud(int n, float size, float jitter, std::uint32_t seed) {
    n = std::max(n, 0);
    jitter = std::clamp(jitter, 0.f, 1.f);
    Pcg32 rng(seed);
    const float cell = n > 0 ? 2.f * size / float(n) : 0.f;
    std::vector<glm::vec3> p;
    p.reserve(static_cast<size_t>(n) * n * n);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::vec3 centre = glm::vec3(-size) + cell * (glm::vec3(i, j, k) + .5f);
                const float x = rng.symmetric(), y = rng.symmetric(), z = rng.symmetric();
                p.push_back(centre + .5f * cell * jitter * glm::vec3(x, y, z));
            }
    return pointsMesh(p, size);
}

Mesh makeTrianglesFrom(const std::vector<glm::vec3>& points) {
    Mesh m;
    m.hasTangents = true;
    for (size_t k = 0; k + 2 < points.size(); k += 3) {
        const glm::vec3 a = points[k], b = points[k + 1], c = points[k + 2];
        const glm::vec3 n = faceNormal(a, b, c);
        const float lac = glm::length(c - a);
        const glm::vec3 tan = lac > 0.f ? (c - a) / lac : glm::vec3(0.f, 1.f, 0.f);
        const glm::vec2 st[3] = {{0.f, 0.f}, {1.f, 0.f}, {0.f, 1.f}};
        for (int i = 0; i < 3; ++i) {
            MeshVertex v;
            v.position = points[k + i];
            v.normal = n;
            v.st = st[i];
            v.tangent = tan;
            m.indices.push_back(static_cast<std::uint32_t>(m.vertices.size()));
            m.vertices.push_back(v);
        }
    }
    m.flat = planar(m);
    return m;
}

Mesh makeLinesAdjacency(const std::vector<glm::vec3>& points) {
    Mesh m;
    m.primitive = Mesh::Primitive::LinesAdjacency;
    const size_t n = points.size() / 4 * 4;
    for (size_t k = 0; k < n; ++k) {
        MeshVertex v;
        v.position = points[k];
        v.st = {float(k % 4) / 3.f, 0.f};
        m.indices.push_back(static_cast<std::uint32_t>(k));
        m.vertices.push_back(v);
    }
    return m;
}

std::optional<ImmediatePrimitive> parseImmediatePrimitive(std::string_view name) {
    std::string s;
    for (char ch : name) s += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (s.rfind("gl_", 0) == 0) s.erase(0, 3);
    static const struct {
        const char* name;
        ImmediatePrimitive p;
    } names[] = {
        {"points", ImmediatePrimitive::Points},
        {"lines", ImmediatePrimitive::Lines},
        {"line_strip", ImmediatePrimitive::LineStrip},
        {"line_loop", ImmediatePrimitive::LineLoop},
        {"triangles", ImmediatePrimitive::Triangles},
        {"triangle_strip", ImmediatePrimitive::TriangleStrip},
        {"triangle_fan", ImmediatePrimitive::TriangleFan},
        {"quads", ImmediatePrimitive::Quads},
        {"quad_strip", ImmediatePrimitive::QuadStrip},
        {"polygon", ImmediatePrimitive::Polygon},
        {"patches", ImmediatePrimitive::Patches},
    };
    for (const auto& e : names)
        if (s == e.name) return e.p;
    return std::nullopt;
}

Mesh makeImmediate(ImmediatePrimitive primitive, const std::vector<glm::vec3>& points) {
    using P = ImmediatePrimitive;
    Mesh m;
    for (const glm::vec3& p : points) {
        MeshVertex v;
        v.position = p;
        m.vertices.push_back(v);
    }
    const auto n = static_cast<std::uint32_t>(points.size());
    auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.indices.insert(m.indices.end(), {a, b, c});
    };
    auto line = [&](std::uint32_t a, std::uint32_t b) { m.indices.insert(m.indices.end(), {a, b}); };
    switch (primitive) {
        case P::Points:
        case P::Patches:
            m.primitive = primitive == P::Points ? Mesh::Primitive::Points : Mesh::Primitive::Patches;
            for (std::uint32_t i = 0; i < n; ++i) m.indices.push_back(i);
            return m;
        case P::Lines:
            m.primitive = Mesh::Primitive::Lines;
            for (std::uint32_t i = 0; i + 1 < n; i += 2) line(i, i + 1);
            return m;
        case P::LineStrip:
        case P::LineLoop:
            m.primitive = Mesh::Primitive::Lines;
            for (std::uint32_t i = 0; i + 1 < n; ++i) line(i, i + 1);
            if (primitive == P::LineLoop && n >= 2) line(n - 1, 0);
            return m;
        case P::Triangles:
            for (std::uint32_t i = 0; i + 2 < n; i += 3) tri(i, i + 1, i + 2);
            break;
        case P::TriangleStrip:
            for (std::uint32_t i = 0; i + 2 < n; ++i) {
                if (i % 2 == 0)
                    tri(i, i + 1, i + 2);
                else
                    tri(i + 1, i, i + 2);
            }
            break;
        case P::TriangleFan:
        case P::Polygon:
            for (std::uint32_t i = 1; i + 1 < n; ++i) tri(0, i, i + 1);
            break;
        case P::Quads:
            for (std::uint32_t i = 0; i + 3 < n; i += 4) {
                tri(i, i + 1, i + 2);
                tri(i, i + 2, i + 3);
            }
            break;
        case P::QuadStrip:
            for (std::uint32_t i = 0; i + 3 < n; i += 2) {
                tri(i, i + 1, i + 3);
                tri(i, i + 3, i + 2);
            }
            break;
    }
    // Triangles: smooth normals from the (area-weighted) face normals.
    std::vector<glm::vec3> sum(m.vertices.size(), glm::vec3(0.f));
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        const glm::vec3 g = glm::cross(m.vertices[b].position - m.vertices[a].position,
                                       m.vertices[c].position - m.vertices[a].position);
        sum[a] += g;
        sum[b] += g;
        sum[c] += g;
    }
    for (size_t i = 0; i < sum.size(); ++i) {
        const float len = glm::length(sum[i]);
        if (len > 0.f && std::isfinite(len)) m.vertices[i].normal = sum[i] / len;
    }
    m.flat = planar(m);
    return m;
}

}  // namespace glimmer
