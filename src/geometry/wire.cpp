// Meshes derived from a triangle mesh's connectivity: wireframes and
// triangles with adjacency.
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "geometry/mesh.h"

namespace glimmer {

namespace {

// For each vertex, the number of the first vertex at the same position
// (within 1e-5 of the mesh's bounding-box diagonal, any axis), so that split
// vertices (per-face normals, texture seams) count as one point.
std::vector<std::uint32_t> weldPositions(const Mesh& m) {
    const size_t n = m.vertices.size();
    std::vector<std::uint32_t> canon(n);
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    for (const MeshVertex& v : m.vertices)
        if (std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z)) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
    const float extent = lo.x <= hi.x ? glm::length(hi - lo) : 0.f;
    const float eps = 1e-5f * extent;
    struct KeyHash {
        size_t operator()(const glm::i64vec3& k) const {
            std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ULL;
            h ^= static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4FULL + (h << 6) + (h >> 2);
            h ^= static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ULL + (h << 6) + (h >> 2);
            return static_cast<size_t>(h);
        }
    };
    std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, KeyHash> cells;
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3 p = m.vertices[i].position;
        canon[i] = static_cast<std::uint32_t>(i);
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) continue;
        const glm::i64vec3 key =
            eps > 0.f ? glm::i64vec3(glm::floor(glm::dvec3(p - lo) / double(eps))) : glm::i64vec3(0);
        bool found = false;
        for (int dz = -1; dz <= 1 && !found; ++dz)
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dx = -1; dx <= 1 && !found; ++dx) {
                    const auto it = cells.find(key + glm::i64vec3(dx, dy, dz));
                    if (it == cells.end()) continue;
                    for (std::uint32_t c : it->second) {
                        const glm::vec3 d = glm::abs(m.vertices[c].position - p);
                        if (std::max({d.x, d.y, d.z}) <= eps) {
                            canon[i] = c;
                            found = true;
                            break;
                        }
                    }
                }
        if (!found) cells[key].push_back(static_cast<std::uint32_t>(i));
    }
    return canon;
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

}  // namespace

Mesh makeWire(const Mesh& solid) {
    Mesh m;
    m.primitive = Mesh::Primitive::Lines;
    m.hasTangents = solid.hasTangents;
    if (solid.primitive != Mesh::Primitive::Triangles) return m;
    const std::vector<std::uint32_t> canon = weldPositions(solid);
    // Mean normal of every position.
    std::vector<glm::vec3> normalSum(solid.vertices.size(), glm::vec3(0.f));
    for (size_t i = 0; i < solid.vertices.size(); ++i) normalSum[canon[i]] += solid.vertices[i].normal;

    std::vector<std::int64_t> out(solid.vertices.size(), -1);  // canonical vertex -> output vertex
    auto vertex = [&](std::uint32_t c) {
        if (out[c] < 0) {
            out[c] = static_cast<std::int64_t>(m.vertices.size());
            MeshVertex v = solid.vertices[c];
            const float len = glm::length(normalSum[c]);
            if (len > 1e-6f && std::isfinite(len)) v.normal = normalSum[c] / len;
            m.vertices.push_back(v);
        }
        return static_cast<std::uint32_t>(out[c]);
    };
    std::unordered_set<std::uint64_t> seen;
    for (size_t t = 0; t + 2 < solid.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t ia = solid.indices[t + k], ib = solid.indices[t + (k + 1) % 3];
            if (ia >= canon.size() || ib >= canon.size()) continue;
            const std::uint32_t a = canon[ia], b = canon[ib];
            if (a == b) continue;
            if (!seen.insert(edgeKey(std::min(a, b), std::max(a, b))).second) continue;
            const std::uint32_t va = vertex(a), vb = vertex(b);
            m.indices.insert(m.indices.end(), {va, vb});
        }
    }
    return m;
}

Mesh makeObjAdjacency(const Mesh& triangles) {
    Mesh m;
    m.primitive = Mesh::Primitive::TrianglesAdjacency;
    if (triangles.primitive != Mesh::Primitive::Triangles) return m;
    m.vertices = triangles.vertices;
    m.hasTangents = triangles.hasTangents;
    const std::vector<std::uint32_t> canon = weldPositions(triangles);
    const size_t numTris = triangles.indices.size() / 3;
    for (std::uint32_t i : triangles.indices)
        if (i >= canon.size()) return Mesh{Mesh::Primitive::TrianglesAdjacency, {}, {}, false, false};

    // Directed edge (by position) -> the triangles running it, with the vertex
    // opposite that edge.
    struct Side {
        size_t tri;
        std::uint32_t opposite;
    };
    std::unordered_map<std::uint64_t, std::vector<Side>> sides;
    for (size_t t = 0; t < numTris; ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = triangles.indices[t * 3 + k], b = triangles.indices[t * 3 + (k + 1) % 3];
            const std::uint32_t c = triangles.indices[t * 3 + (k + 2) % 3];
            if (canon[a] != canon[b]) sides[edgeKey(canon[a], canon[b])].push_back({t, c});
        }
    auto across = [&](std::uint64_t key, size_t self) -> std::int64_t {
        const auto it = sides.find(key);
        if (it == sides.end()) return -1;
        for (const Side& s : it->second)
            if (s.tri != self) return s.opposite;
        return -1;
    };
    m.indices.reserve(numTris * 6);
    for (size_t t = 0; t < numTris; ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = triangles.indices[t * 3 + k], b = triangles.indices[t * 3 + (k + 1) % 3];
            const std::uint32_t c = triangles.indices[t * 3 + (k + 2) % 3];
            std::int64_t adj = -1;
            if (canon[a] != canon[b]) {
                adj = across(edgeKey(canon[b], canon[a]), t);               // consistently wound neighbour
                if (adj < 0) adj = across(edgeKey(canon[a], canon[b]), t);  // flipped neighbour
            }
            m.indices.push_back(a);
            m.indices.push_back(adj < 0 ? c : static_cast<std::uint32_t>(adj));
        }
    return m;
}

}  // namespace glimmer
