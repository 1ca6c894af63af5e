// Pieces the shape makers share; not part of the geometry layer's interface.
#pragma once
#include "geometry/mesh.h"

namespace glimmer {

// One quad face as 4 vertices and 2 triangles: corners at centre +- sHalf +-
// tHalf, s and t running 0..1 along sHalf and tHalf, counter-clockwise seen
// from where sHalf x tHalf points.
void appendQuadFace(Mesh& m, glm::vec3 centre, glm::vec3 sHalf, glm::vec3 tHalf, glm::vec3 normal, glm::vec3 tangent);

}  // namespace glimmer
