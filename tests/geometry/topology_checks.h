// Connectivity checks by position (independent of the code under test's own
// welding): closed surfaces, boundary edges, unique wire edges.
#pragma once
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "geometry/mesh.h"

namespace glimmer::test {

using PosKey = std::tuple<long, long, long>;

// Positions rounded to 1e-4: coincident vertices computed a little
// differently (a sphere's seam) still meet.
inline PosKey posKey(glm::vec3 p) {
    return {std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f)};
}

// Directed edges of the triangles, by position, with how often each occurs;
// degenerate triangles (two corners at one position) are skipped.
inline std::map<std::pair<PosKey, PosKey>, int> directedEdges(const Mesh& m) {
    std::map<std::pair<PosKey, PosKey>, int> e;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        PosKey k[3];
        for (int i = 0; i < 3; ++i) k[i] = posKey(m.vertices[m.indices[t + i]].position);
        if (k[0] == k[1] || k[1] == k[2] || k[2] == k[0]) continue;
        for (int i = 0; i < 3; ++i) ++e[{k[i], k[(i + 1) % 3]}];
    }
    return e;
}

// Closed and consistently oriented: every directed edge occurs exactly once
// and so does its reverse.
inline void expectClosedOriented(const Mesh& m) {
    const auto e = directedEdges(m);
    ASSERT_FALSE(e.empty());
    for (const auto& [edge, count] : e) {
        ASSERT_EQ(count, 1) << "edge used twice in one direction";
        const auto rev = e.find({edge.second, edge.first});
        ASSERT_TRUE(rev != e.end()) << "open edge";
        ASSERT_EQ(rev->second, 1);
    }
}

// Undirected edges used by exactly one triangle.
inline int boundaryEdgeCount(const Mesh& m) {
    std::map<std::pair<PosKey, PosKey>, int> u;
    for (const auto& [edge, count] : directedEdges(m))
        u[std::minmax(edge.first, edge.second)] += count;
    int n = 0;
    for (const auto& [edge, count] : u) n += count == 1;
    return n;
}

// Distinct undirected edges (by position) of a triangle mesh.
inline size_t uniqueEdgeCount(const Mesh& m) {
    std::set<std::pair<PosKey, PosKey>> u;
    for (const auto& [edge, count] : directedEdges(m)) u.insert(std::minmax(edge.first, edge.second));
    return u.size();
}

inline size_t uniquePositionCount(const Mesh& m) {
    std::set<PosKey> s;
    for (const MeshVertex& v : m.vertices) s.insert(posKey(v.position));
    return s.size();
}

inline void expectFinite(const Mesh& m) {
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        const MeshVertex& v = m.vertices[i];
        for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(std::isfinite(v.position[k])) << "vertex " << i;
            ASSERT_TRUE(std::isfinite(v.normal[k])) << "vertex " << i;
            ASSERT_TRUE(std::isfinite(v.tangent[k])) << "vertex " << i;
        }
        ASSERT_TRUE(std::isfinite(v.st.s) && std::isfinite(v.st.t)) << "vertex " << i;
    }
}

}  // namespace glimmer::test
