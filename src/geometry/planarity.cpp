#include "geometry/planarity.h"

#include <algorithm>
#include <cmath>

namespace glimmer {

bool coplanar(const std::vector<glm::dvec3>& p) {
    const size_t n = p.size();
    if (n < 4) return true;
    glm::dvec3 lo = p[0], hi = p[0];
    for (const auto& q : p) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    const double eps = 1e-6 * std::max(glm::length(hi - lo), 1e-30);
    size_t a = 0;
    double far = 0;
    for (size_t i = 1; i < n; ++i)
        if (double d = glm::length(p[i] - p[0]); d > far) far = d, a = i;
    if (far <= eps) return true;  // all at one point
    glm::dvec3 normal(0.0);
    for (size_t i = 1; i < n; ++i) {
        glm::dvec3 c = glm::cross(p[a] - p[0], p[i] - p[0]);
        if (glm::length(c) > glm::length(normal)) normal = c;
    }
    // |normal| = |a - p0| * distance of the point from the line p0-a.
    if (glm::length(normal) <= eps * far) return true;  // all on one line
    normal = glm::normalize(normal);
    for (const auto& q : p)
        if (std::abs(glm::dot(q - p[0], normal)) > eps) return false;
    return true;
}

}  // namespace glimmer
