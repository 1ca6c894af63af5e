#include "plan/hidden_clears.h"

#include <array>

namespace glimmer {
namespace {

// 2D cross product of (b - a) and (p - a): its sign says which side of the
// line a->b the point p is on.
double side(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Whether p is inside (or on) the convex quadrilateral q, either winding.
bool insideConvex(const std::array<glm::dvec2, 4>& q, const glm::dvec2& p) {
    bool anyPositive = false, anyNegative = false;
    for (size_t i = 0; i < 4; ++i) {
        double s = side(q[i], q[(i + 1) % 4], p);
        anyPositive |= s > 0;
        anyNegative |= s < 0;
    }
    return !(anyPositive && anyNegative);
}

}  // namespace

bool coversViewport(const MeshDecl& mesh, const glm::mat4& clipFromObject) {
    glm::vec3 centre, s, t;
    switch (mesh.shape) {  // makeQuad's frames (geometry/shapes.cpp)
    case CommandKind::QuadXY: centre = {0, 0, 1}, s = {1, 0, 0}, t = {0, 1, 0}; break;
    case CommandKind::QuadXZ: centre = {0, 1, 0}, s = {1, 0, 0}, t = {0, 0, 1}; break;
    case CommandKind::QuadYZ: centre = {1, 0, 0}, s = {0, 1, 0}, t = {0, 0, 1}; break;
    default: return false;
    }
    if (mesh.params.size() < 2) return false;
    const float offset = float(mesh.params[0]), size = float(mesh.params[1]);
    centre *= offset;
    // Corners in order around the quad: (-,-), (+,-), (+,+), (-,+).
    std::array<glm::dvec2, 4> corners;
    const float signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (size_t i = 0; i < 4; ++i) {
        glm::vec4 clip = clipFromObject * glm::vec4(centre + signs[i][0] * size * s + signs[i][1] * size * t, 1.f);
        // Behind the eye, or cut by the near or far plane: not a plain quad on screen.
        if (!(clip.w > 0) || clip.z < -clip.w || clip.z > clip.w) return false;
        corners[i] = {double(clip.x) / clip.w, double(clip.y) / clip.w};
    }
    for (const glm::dvec2 viewport : {glm::dvec2{-1, -1}, glm::dvec2{1, -1}, glm::dvec2{1, 1}, glm::dvec2{-1, 1}})
        if (!insideConvex(corners, viewport)) return false;
    return true;
}

void markHiddenClears(Plan& plan) {
    for (Pass& pass : plan.passes) {
        if (pass.needsDepth || pass.targets.size() > 1) continue;
        for (size_t i = 0; i < pass.steps.size(); ++i) {
            Step& clear = pass.steps[i];
            if (clear.kind != Step::Kind::Clear) continue;
            clear.hiddenBy = -1;
            for (size_t j = i + 1; j < pass.steps.size() && clear.hiddenBy < 0; ++j) {
                const Step& s = pass.steps[j];
                if (s.kind == Step::Kind::Draw && s.draw.mesh >= 0 &&
                    coversViewport(plan.meshes[size_t(s.draw.mesh)], s.draw.projection * s.draw.modelView))
                    clear.hiddenBy = int(j);
            }
        }
    }
}

}  // namespace glimmer
