// How big a stand-in for a missing model must be to be seen. A course's
// script sets its view for its model (Ortho -60 60 for a 60-unit dragon, or
// a Scale .01 around a model in millimetres); a unit sphere in its place may
// be three pixels wide, or fill the screen. The stand-in is sized instead to
// the space the script gives the object. No OpenGL: matrices only.
#pragma once
#include <glm/glm.hpp>

namespace glimmer {

// What a stand-in covers of the view's height, centred where the object sits.
constexpr float kStandInViewShare = .4f;

// The radius, in the object's own units, of a sphere at the object's origin
// that spans kStandInViewShare of the view's height under `projection` and
// `modelView`; 1 when the origin is not in front of the eye or the matrices
// collapse it (then nothing better is known).
float standInRadius(const glm::mat4& projection, const glm::mat4& modelView);

}  // namespace glimmer
