// What the glman property tests (properties_test.cpp, properties_more_test.cpp)
// share: the rendered pictures, the script's camera applied by hand with GLM,
// pixel colours and extents, lit.frag's lighting formula.
#pragma once
#include <algorithm>
#include <cmath>
#include <set>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "glman_harness.h"

namespace glimmer::glmantest {

constexpr int kSize = 96;  // every script here has WindowSize 96 96

inline Image rendered(const char* name) {
    auto r = glimmer::testing::renderScript("osmesa", script(name), {}, {});
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.screen.width, kSize);
    EXPECT_EQ(r.screen.height, kSize);
    if (r.screen.width != kSize || r.screen.height != kSize) return Image::rgba8(kSize, kSize);
    return r.screen;
}

inline glm::mat4 rotate(float degrees, float x, float y, float z) {
    return glm::rotate(glm::mat4(1.f), glm::radians(degrees), glm::vec3(x, y, z));
}
inline glm::mat4 ortho(float h) { return glm::ortho(-h, h, -h, h, -1000.f, 1000.f); }
inline glm::mat4 lookAt(glm::vec3 eye, glm::vec3 at, glm::vec3 up) { return glm::lookAt(eye, at, up); }

// Window coordinates of a point: x to the right, y down from the top, in
// pixels (pixel (i, j) covers [i, i+1) x [j, j+1)).
inline glm::vec2 toPixel(const glm::mat4& mvp, glm::vec3 p) {
    glm::vec4 c = mvp * glm::vec4(p, 1.f);
    return {(c.x / c.w + 1.f) * .5f * kSize, (1.f - c.y / c.w) * .5f * kSize};
}

struct Rgb {
    int r, g, b;
};
inline Rgb at(const Image& img, int x, int y) {
    const std::uint8_t* p = pixel(img, x, y);
    return {p[0], p[1], p[2]};
}
inline bool isBlack(Rgb c) { return c.r + c.g + c.b == 0; }

// The pixels of exactly this colour: their column range and row range.
struct Extent {
    int minX = kSize, maxX = -1, minY = kSize, maxY = -1;
    long count = 0;
};
template <class Pred>
inline Extent extentOf(const Image& img, Pred pred) {
    Extent e;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            if (pred(at(img, x, y))) {
                e.minX = std::min(e.minX, x);
                e.maxX = std::max(e.maxX, x);
                e.minY = std::min(e.minY, y);
                e.maxY = std::max(e.maxY, y);
                ++e.count;
            }
    return e;
}
inline auto exactly(int r, int g, int b) {
    return [=](Rgb c) { return c.r == r && c.g == g && c.b == b; };
}

// lit.frag: colour x (0.25 + 0.75 max(N.L, 0)), L = (-1, 1, 1)/sqrt 3 in eye space.
inline double litFactor(glm::vec3 eyeNormal) {
    glm::vec3 L = glm::normalize(glm::vec3(-1.f, 1.f, 1.f));
    return 0.25 + 0.75 * std::max(0.0, double(glm::dot(glm::normalize(eyeNormal), L)));
}

inline float meshMinX(const Mesh& m, float s) {
    float v = 1e9f;
    for (const auto& p : m.vertices) v = std::min(v, p.position.x * s);
    return v;
}
inline float meshMaxX(const Mesh& m, float s) {
    float v = -1e9f;
    for (const auto& p : m.vertices) v = std::max(v, p.position.x * s);
    return v;
}

// How far p is from the segment a-b, in pixels.
inline double distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    glm::vec2 ab = b - a;
    float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f);
    return glm::length(p - (a + t * ab));
}

}  // namespace glimmer::glmantest
