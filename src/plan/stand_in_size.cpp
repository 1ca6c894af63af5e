#include "plan/stand_in_size.h"

#include <cmath>

namespace glimmer {

float standInRadius(const glm::mat4& projection, const glm::mat4& modelView) {
    // The object's origin in eye space, and how far one eye-space unit up
    // from it moves on the screen (normalised device coordinates, 2 = the
    // view's height): a perspective shrinks it with distance, an Ortho not.
    const glm::vec4 eye = modelView * glm::vec4(0.f, 0.f, 0.f, 1.f);
    const glm::vec4 c0 = projection * eye;
    const glm::vec4 c1 = projection * (eye + glm::vec4(0.f, 1.f, 0.f, 0.f));
    if (!(c0.w > 1e-6f) || !(c1.w > 1e-6f)) return 1.f;
    const float ndcPerEyeUnit = std::abs(c1.y / c1.w - c0.y / c0.w);
    // How long one object unit is in eye space (the transforms around the
    // object: Scale .01 makes it short), the mean over the three axes.
    const float eyePerObjectUnit = (glm::length(glm::vec3(modelView[0])) + glm::length(glm::vec3(modelView[1])) +
                                    glm::length(glm::vec3(modelView[2]))) / 3.f;
    const float perObjectUnit = ndcPerEyeUnit * eyePerObjectUnit;
    if (!std::isfinite(perObjectUnit) || perObjectUnit < 1e-20f) return 1.f;
    const float radius = kStandInViewShare / perObjectUnit;  // a diameter of 2 r spans 2 * share
    return std::isfinite(radius) && radius > 0.f && radius < 1e30f ? radius : 1.f;
}

}  // namespace glimmer
