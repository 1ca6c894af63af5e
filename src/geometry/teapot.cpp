// The Newell teapot: the published Bezier patches (teapot_data.cpp)
// evaluated on a grid, turned Y up and scaled like glutSolidTeapot.
#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/mesh.h"
#include "geometry/teapot_data.h"

namespace glimmer {

namespace {

using Patch = std::array<glm::vec3, 16>;  // row-major: [row * 4 + column]

// Cubic and quadratic Bernstein bases at x.
void bernstein3(float x, float b[4]) {
    const float y = 1.f - x;
    b[0] = y * y * y;
    b[1] = 3.f * x * y * y;
    b[2] = 3.f * x * x * y;
    b[3] = x * x * x;
}
void bernstein2(float x, float b[3]) {
    const float y = 1.f - x;
    b[0] = y * y;
    b[1] = 2.f * x * y;
    b[2] = x * x;
}

// de Casteljau on 4 points, in the a + x (b - a) form: where all four are
// the same point (a collapsed patch row) the result is exactly that point.
glm::vec3 casteljau(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, float x) {
    auto lerp = [x](glm::vec3 p, glm::vec3 q) { return p + x * (q - p); };
    const glm::vec3 ab = lerp(a, b), bc = lerp(b, c), cd = lerp(c, d);
    return lerp(lerp(ab, bc), lerp(bc, cd));
}

struct Sample {
    glm::vec3 p, ds, dt;  // position, d/d s (along a row), d/d t (across rows)
};

Sample evaluate(const Patch& cp, float s, float t) {
    auto at = [&cp](int row, int col) { return cp[row * 4 + col]; };
    glm::vec3 rows[4];
    for (int r = 0; r < 4; ++r) rows[r] = casteljau(at(r, 0), at(r, 1), at(r, 2), at(r, 3), s);
    Sample out{casteljau(rows[0], rows[1], rows[2], rows[3], t), glm::vec3(0.f), glm::vec3(0.f)};
    // Derivatives from differences of control points (the hodograph): a
    // collapsed row gives exactly zero rather than rounding noise.
    float b3s[4], b3t[4], b2s[3], b2t[3];
    bernstein3(s, b3s);
    bernstein3(t, b3t);
    bernstein2(s, b2s);
    bernstein2(t, b2t);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 3; ++c) out.ds += 3.f * b3t[r] * b2s[c] * (at(r, c + 1) - at(r, c));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out.dt += 3.f * b2t[r] * b3s[c] * (at(r + 1, c) - at(r, c));
    return out;
}

// Outward normal and unit d/dt at (s, t), in the Newell frame (Z up). Where a
// patch edge collapses to a point (lid knob top, bottom centre) the
// derivatives vanish: take them a little way into the patch instead, and on
// the Z axis use the axis itself, pointing the way the nearby normal does.
void frame(const Patch& cp, const Sample& at, float s, float t, glm::vec3& normal, glm::vec3& tangent) {
    auto cross = [](const Sample& x) { return glm::cross(x.ds, x.dt); };
    const float tiny = 1e-12f;
    glm::vec3 n = cross(at), dt = at.dt;
    if (glm::length(n) <= tiny || glm::length(dt) <= tiny) {
        const float e = 1e-3f;
        const Sample near = evaluate(cp, std::clamp(s, e, 1.f - e), std::clamp(t, e, 1.f - e));
        if (glm::length(n) <= tiny) n = cross(near);
        if (glm::length(dt) <= tiny) dt = near.dt;
        if (std::abs(at.p.x) < 1e-5f && std::abs(at.p.y) < 1e-5f && glm::length(n) > 0.f)
            n = {0.f, 0.f, n.z >= 0.f ? 1.f : -1.f};
    }
    normal = glm::length(n) > 0.f ? glm::normalize(n) : glm::vec3(0.f, 0.f, 1.f);
    tangent = glm::length(dt) > 0.f ? glm::normalize(dt) : glm::vec3(0.f, 0.f, 1.f);
}

// Newell's Z-up frame to glutSolidTeapot's: rotate -90 degrees about X.
glm::vec3 yUp(glm::vec3 v) { return {v.x, v.z, -v.y}; }

}  // namespace

Mesh makeTeapot(float size, int subdivisions) {
    const int n = std::max(subdivisions, 1);
    const float scale = .5f * size;
    Mesh m;
    m.hasTangents = true;
    m.vertices.reserve(static_cast<size_t>(teapot::kNumPatches) * (n + 1) * (n + 1));
    m.indices.reserve(static_cast<size_t>(teapot::kNumPatches) * n * n * 6);
    for (const auto& indices : teapot::kPatches) {
        Patch cp;
        for (int k = 0; k < 16; ++k) {
            const float* v = teapot::kVertices[indices[k] - 1];
            cp[k] = {v[0], v[1], v[2]};
        }
        const auto base = static_cast<std::uint32_t>(m.vertices.size());
        for (int j = 0; j <= n; ++j) {
            const float t = float(j) / float(n);
            for (int i = 0; i <= n; ++i) {
                const float s = float(i) / float(n);
                const Sample at = evaluate(cp, s, t);
                glm::vec3 normal, tangent;
                frame(cp, at, s, t, normal, tangent);
                MeshVertex v;
                // glutSolidTeapot: translate by -1.5 in Z, scale by size/2, turn Y up.
                v.position = scale * yUp(at.p - glm::vec3(0.f, 0.f, 1.5f));
                v.normal = yUp(normal);
                v.tangent = yUp(tangent);
                v.st = {s, t};
                m.vertices.push_back(v);
            }
        }
        // d/ds x d/dt points outward: s then t is counter-clockwise from outside.
        const auto stride = static_cast<std::uint32_t>(n + 1);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::uint32_t a = base + j * stride + i, b = a + 1, c = b + stride, d = a + stride;
                m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
            }
    }
    return m;
}

}  // namespace glimmer
