// coplanar(): the one test of whether a shape can hide part of itself.
#include <gtest/gtest.h>

#include "geometry/planarity.h"

namespace glimmer {
namespace {

TEST(Planarity, FewPointsAndLinesAreFlat) {
    EXPECT_TRUE(coplanar({}));
    EXPECT_TRUE(coplanar({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_TRUE(coplanar({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}));  // one line
    EXPECT_TRUE(coplanar({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}));  // one point
}

TEST(Planarity, APointOffThePlaneIsNotFlat) {
    std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    EXPECT_TRUE(coplanar(p));
    p.push_back({0.5, 0.5, 1e-3});
    EXPECT_FALSE(coplanar(p));
}

TEST(Planarity, ManyCollinearPointsBeforeTheFirstTurn) {
    // The old test looked for a spanning pair among all pairs: quadratic on
    // exactly this input. 200k points along x, then one off the line.
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 200000; ++i) p.push_back({double(i), 0, 0});
    p.push_back({0, 1, 0});
    EXPECT_TRUE(coplanar(p));
    p.push_back({0, 0, 5});
    EXPECT_FALSE(coplanar(p));
}

TEST(Planarity, TiltedPlaneWithinTolerance) {
    std::vector<glm::dvec3> p;
    glm::dvec3 u = glm::normalize(glm::dvec3(1, 2, 3)), v = glm::normalize(glm::cross(u, glm::dvec3(0, 0, 1)));
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) p.push_back(u * double(i) + v * double(j) + glm::dvec3(5, -2, 7));
    EXPECT_TRUE(coplanar(p));
}

}  // namespace
}  // namespace glimmer
