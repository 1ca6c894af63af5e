// Whether points lie in one plane: the one test of "can this shape hide part
// of itself" (a flat shape drawn alone needs no depth buffer). Used by the
// shape builders (Mesh::flat) and by the plan (MeshDecl::flat), which must
// agree on it.
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace glimmer {

// True when every point lies within 1e-6 of the points' extent of one plane
// (fewer than four points, or all on one line, always do). Linear in the
// number of points: the plane is spanned by the point farthest from the
// first and the point farthest from that line, the two that make the
// normal best conditioned.
bool coplanar(const std::vector<glm::dvec3>& points);

}  // namespace glimmer
