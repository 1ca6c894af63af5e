// The glman pictures that golden_test.cpp only compares with earlier output,
// each checked for at least one property worked out here, independently of
// the renderer: where a shape must land (the script's camera applied by hand
// with GLM), the colour a face must have (the shader's formula), how many
// vertices a tessellation makes, the statistics of noise, which cube-map face
// an axis reads. A picture that is wrong but stable fails here.
#include <algorithm>
#include <cmath>
#include <set>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "glman_harness.h"

using namespace glimmer;
using namespace glimmer::glmantest;

namespace {

constexpr int kSize = 96;  // every script here has WindowSize 96 96

Image rendered(const char* name) {
    auto r = glimmer::testing::renderScript("osmesa", script(name), {}, {});
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.screen.width, kSize);
    EXPECT_EQ(r.screen.height, kSize);
    if (r.screen.width != kSize || r.screen.height != kSize) return Image::rgba8(kSize, kSize);
    return r.screen;
}

glm::mat4 rotate(float degrees, float x, float y, float z) {
    return glm::rotate(glm::mat4(1.f), glm::radians(degrees), glm::vec3(x, y, z));
}
glm::mat4 ortho(float h) { return glm::ortho(-h, h, -h, h, -1000.f, 1000.f); }
glm::mat4 lookAt(glm::vec3 eye, glm::vec3 at, glm::vec3 up) { return glm::lookAt(eye, at, up); }

// Window coordinates of a point: x to the right, y down from the top, in
// pixels (pixel (i, j) covers [i, i+1) x [j, j+1)).
glm::vec2 toPixel(const glm::mat4& mvp, glm::vec3 p) {
    glm::vec4 c = mvp * glm::vec4(p, 1.f);
    return {(c.x / c.w + 1.f) * .5f * kSize, (1.f - c.y / c.w) * .5f * kSize};
}

struct Rgb {
    int r, g, b;
};
Rgb at(const Image& img, int x, int y) {
    const std::uint8_t* p = pixel(img, x, y);
    return {p[0], p[1], p[2]};
}
bool isBlack(Rgb c) { return c.r + c.g + c.b == 0; }

// The pixels of exactly this colour: their column range and row range.
struct Extent {
    int minX = kSize, maxX = -1, minY = kSize, maxY = -1;
    long count = 0;
};
template <class Pred>
Extent extentOf(const Image& img, Pred pred) {
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
auto exactly(int r, int g, int b) {
    return [=](Rgb c) { return c.r == r && c.g == g && c.b == b; };
}

// lit.frag: colour x (0.25 + 0.75 max(N.L, 0)), L = (-1, 1, 1)/sqrt 3 in eye space.
double litFactor(glm::vec3 eyeNormal) {
    glm::vec3 L = glm::normalize(glm::vec3(-1.f, 1.f, 1.f));
    return 0.25 + 0.75 * std::max(0.0, double(glm::dot(glm::normalize(eyeNormal), L)));
}

float meshMinX(const Mesh& m, float s) {
    float v = 1e9f;
    for (const auto& p : m.vertices) v = std::min(v, p.position.x * s);
    return v;
}
float meshMaxX(const Mesh& m, float s) {
    float v = -1e9f;
    for (const auto& p : m.vertices) v = std::max(v, p.position.x * s);
    return v;
}

// ---- teapot.glib ------------------------------------------------------------
// Under LookAt 0 1 4 -> origin (no turn about Y) and Ortho -2 2, screen x is
// world x: column = 24 (x + 2). The solid teapot is lit.frag's (1 .6 .2) x k
// and the wire one (.4 .8 1) x k, k in [.25, 1]; their columns span the
// teapot's x extent times .8 and .7.
TEST(GlmanProperties, TeapotHuesFromTheLightingFormulaAndItsWidth) {
    Image img = rendered("teapot");
    long orange = 0, blue = 0, other = 0;
    int maxOrange = 0, minOrange = 255, minBlue = 255;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Rgb c = at(img, x, y);
            if (isBlack(c)) continue;
            if (c.r > c.b && std::abs(c.g - 0.6 * c.r) <= 2 && std::abs(c.b - 0.2 * c.r) <= 2) {
                ++orange;
                maxOrange = std::max(maxOrange, c.r);
                minOrange = std::min(minOrange, c.r);
            } else if (c.b > c.r && std::abs(c.r - 0.4 * c.b) <= 2 && std::abs(c.g - 0.8 * c.b) <= 2) {
                ++blue;
                minBlue = std::min(minBlue, c.b);
            } else {
                ++other;
            }
        }
    EXPECT_EQ(other, 0) << "pixels that are neither teapot's colour times a light factor";
    EXPECT_GT(orange, 1000);
    EXPECT_GT(blue, 300);
    EXPECT_GE(minOrange, 63);   // ambient 0.25 x 255
    EXPECT_GE(minBlue, 63);
    EXPECT_GE(maxOrange, 240);  // some normal faces the light
    Mesh pot = makeTeapot(1.f);
    Extent top = extentOf(img, [](Rgb c) { return c.r > c.b && c.r > 0; });
    Extent bottom = extentOf(img, [](Rgb c) { return c.b > c.r; });
    EXPECT_NEAR(top.minX, 24 * (meshMinX(pot, .8f) + 2), 1.5);
    EXPECT_NEAR(top.maxX + 1, 24 * (meshMaxX(pot, .8f) + 2), 1.5);
    EXPECT_NEAR(bottom.minX, 24 * (meshMinX(pot, .7f) + 2), 1.5);
    EXPECT_NEAR(bottom.maxX + 1, 24 * (meshMaxX(pot, .7f) + 2), 1.5);
    // The solid one above the wire one.
    EXPECT_LT(top.maxY, bottom.maxY);
}

// ---- cone_cylinder_disk.glib ------------------------------------------------
// The disk is flat, normal +Z: one colour, (.3 .5 1) x the light factor of
// +Z turned into eye space by LookAt 0 2 6 -> 0 .3 0.
TEST(GlmanProperties, DiskColourIsTheLightingFormulaOfItsNormal) {
    Image img = rendered("cone_cylinder_disk");
    glm::mat4 view = lookAt({0, 2, 6}, {0, .3f, 0}, {0, 1, 0});
    glm::mat4 proj = glm::perspective(glm::radians(50.f), 1.f, .1f, 1000.f);
    double k = litFactor(glm::mat3(view) * glm::vec3(0, 0, 1));
    glm::vec2 centre = toPixel(proj * view, {1.6f, .6f, 0.f});
    Rgb c = at(img, int(centre.x), int(centre.y));
    EXPECT_NEAR(c.r, .3 * k * 255, 1.0);
    EXPECT_NEAR(c.g, .5 * k * 255, 1.0);
    EXPECT_NEAR(c.b, 1.0 * k * 255, 1.0);
    // The disk's radius .7 at its distance: the pixels of that one colour
    // reach from the centre to the projected rim, left and right.
    Extent disk = extentOf(img, exactly(c.r, c.g, c.b));
    glm::vec2 left = toPixel(proj * view, {1.6f - .7f, .6f, 0.f});
    glm::vec2 right = toPixel(proj * view, {1.6f + .7f, .6f, 0.f});
    EXPECT_NEAR(disk.minX, left.x, 1.5);
    EXPECT_NEAR(disk.maxX + 1, right.x, 1.5);
}

// ---- wire_shapes.glib -------------------------------------------------------
// Ortho -3 3 with LookAt 0 2 8 -> origin only tilts about X: column = 16 (x + 3).
// Each shape's colour spans its x extent: the box +-.6, a 10-slice sphere
// .7 sin 72, a torus outer + inner = .85, a 10-slice cone .7 sin 72, a
// 10-slice cylinder .6 sin 72, the tetrahedron +-1 scaled .6.
TEST(GlmanProperties, WireShapesSpanTheirWidthsWhereTheScriptPutsThem) {
    Image img = rendered("wire_shapes");
    EXPECT_NEAR(at(img, 1, 1).r, 26, 1);  // Background .1
    const double s72 = std::sin(72.0 * M_PI / 180.0);
    struct Shape {
        const char* name;
        int r, g, b;
        double cx, halfWidth;
    } shapes[] = {{"WireBox", 255, 255, 0, -2, .6},         {"WireSphere", 0, 255, 255, 0, .7 * s72},
                  {"WireTorus", 255, 0, 255, 2, .85},       {"WireCone", 255, 128, 0, -2, .7 * s72},
                  {"WireCylinder", 128, 255, 128, 0, .6 * s72}, {"WireObj", 255, 255, 255, 2, .6}};
    for (const auto& s : shapes) {
        Extent e = extentOf(img, [&](Rgb c) {
            return std::abs(c.r - s.r) <= 1 && std::abs(c.g - s.g) <= 1 && std::abs(c.b - s.b) <= 1;
        });
        ASSERT_GT(e.count, 20) << s.name;
        EXPECT_NEAR(e.minX + .5, 16 * (s.cx - s.halfWidth + 3), 1.5) << s.name;
        EXPECT_NEAR(e.maxX + .5, 16 * (s.cx + s.halfWidth + 3), 1.5) << s.name;
    }
}

// ---- objadj.glib ------------------------------------------------------------
// The tetrahedron under the script's turns: the bright (1 1 0) edges are its
// silhouette, the outline of the projected vertices, and the dim (.2 .2 .6)
// edge is the one inner edge between the two front faces.
double distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    glm::vec2 ab = b - a;
    float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f);
    return glm::length(p - (a + t * ab));
}

TEST(GlmanProperties, ObjAdjSilhouetteIsTheOutlineOfTheProjectedTetrahedron) {
    Image img = rendered("objadj");
    glm::mat4 mv = lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0}) * rotate(30, 0, 1, 0) * rotate(20, 1, 0, 0) *
                   rotate(70, 0, 0, 1) * rotate(60, 1, 0, 0);
    glm::mat4 mvp = ortho(2) * mv;
    const glm::vec3 v[4] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
    glm::vec2 p[4];
    for (int i = 0; i < 4; ++i) p[i] = toPixel(mvp, v[i]);
    // Which pairs are outline edges: a segment is on the outline when the
    // other two points lie on the same side of it.
    auto side = [](glm::vec2 a, glm::vec2 b, glm::vec2 c) {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    };
    std::vector<std::pair<int, int>> outline, inner;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            std::vector<int> others;
            for (int m = 0; m < 4; ++m)
                if (m != i && m != j) others.push_back(m);
            bool same = side(p[i], p[j], p[others[0]]) * side(p[i], p[j], p[others[1]]) > 0;
            (same ? outline : inner).push_back({i, j});
        }
    ASSERT_EQ(outline.size(), 4u) << "all four vertices on the outline (as this view has it)";
    ASSERT_EQ(inner.size(), 2u);
    long yellow = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Rgb c = at(img, x, y);
            glm::vec2 q(x + .5f, y + .5f);
            if (c.r == 255 && c.g == 255 && c.b == 0) {
                ++yellow;
                double d = 1e9;
                for (auto [i, j] : outline) d = std::min(d, distanceToSegment(q, p[i], p[j]));
                EXPECT_LE(d, 1.5) << "yellow pixel " << x << "," << y << " off the outline";
            } else if (std::abs(c.r - 51) <= 1 && std::abs(c.b - 153) <= 1) {
                double d = 1e9;
                for (auto [i, j] : inner) d = std::min(d, distanceToSegment(q, p[i], p[j]));
                EXPECT_LE(d, 1.5) << "dim pixel " << x << "," << y << " off the inner edges";
            } else {
                EXPECT_TRUE(isBlack(c)) << x << "," << y;
            }
        }
    // And every outline edge is drawn: its midpoint has yellow beside it.
    for (auto [i, j] : outline) {
        glm::vec2 m = (p[i] + p[j]) * .5f;
        bool found = false;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                Rgb c = at(img, int(m.x) + dx, int(m.y) + dy);
                found |= c.r == 255 && c.g == 255 && c.b == 0;
            }
        EXPECT_TRUE(found) << "outline edge " << i << "-" << j;
    }
    EXPECT_GT(yellow, 100);
}

// ---- triangles_linesadj.glib and glbegin.glib: pixel = 24 (x + 2), 24 (2 - y)
glm::ivec2 px2(double x, double y) { return {int(24 * (x + 2)), int(24 * (2 - y))}; }

TEST(GlmanProperties, TrianglesAndLinesAdjacencyWhereTheirCoordinatesSay) {
    Image img = rendered("triangles_linesadj");
    auto is = [&](double x, double y, int r, int g, int b) {
        glm::ivec2 p = px2(x, y);
        Rgb c = at(img, p.x, p.y);
        return std::abs(c.r - r) <= 1 && std::abs(c.g - g) <= 1 && std::abs(c.b - b) <= 1;
    };
    EXPECT_TRUE(is(-1.2, -1.2, 255, 128, 0));  // inside [-1.8 -1.8] [0 -1.8] [-1.8 0]
    EXPECT_TRUE(is(-.5, -.5, 0, 0, 0));        // beyond its hypotenuse
    EXPECT_TRUE(is(.5, .5, 255, 128, 0));      // inside [0 0] [1.8 0] [0 1.8]
    EXPECT_TRUE(is(-.5, .5, 0, 0, 0));
    // linesadj.geom draws v1-v2 = (.4 -1.2)-(1.6 -1.2) in cyan, and ticks 30%
    // of the way to v0 and v3; nothing further out.
    glm::ivec2 mid = px2(1.0, -1.2);
    bool cyan = false;
    for (int dy = -1; dy <= 1; ++dy) {
        Rgb c = at(img, mid.x, mid.y + dy);
        cyan |= c.r == 0 && c.g == 255 && c.b == 255;
    }
    EXPECT_TRUE(cyan);
    Extent line = extentOf(img, exactly(0, 255, 255));
    // From .4 + .3 (0 - .4) = .28 to 1.6 + .3 (1.8 - 1.6) = 1.66; rows from
    // -1.2 + .3 (-1.8 + 1.2) = -1.38 up to -1.2 + .3 (-.2 + 1.2) = -.9.
    EXPECT_NEAR(line.minX + .5, 24 * (.28 + 2), 1.5);
    EXPECT_NEAR(line.maxX + .5, 24 * (1.66 + 2), 1.5);
    EXPECT_NEAR(line.minY + .5, 24 * (2 - -.9), 1.5);
    EXPECT_NEAR(line.maxY + .5, 24 * (2 - -1.38), 1.5);
}

TEST(GlmanProperties, GlBeginPrimitivesWhereTheirVerticesSay) {
    Image img = rendered("glbegin");
    // The triangle fan is the square -1.8..-.2 x .2..1.8, red.
    Extent red = extentOf(img, exactly(255, 0, 0));
    EXPECT_EQ(red.minX, int(24 * (-1.8 + 2) + .5));
    EXPECT_EQ(red.maxX + 1, int(24 * (-.2 + 2) + .5));
    EXPECT_EQ(red.minY, int(24 * (2 - 1.8) + .5));
    EXPECT_EQ(red.maxY + 1, int(24 * (2 - .2) + .5));
    EXPECT_EQ(red.count, long(red.maxX - red.minX + 1) * (red.maxY - red.minY + 1));  // filled
    // gl_quads: .2..1.8 x -1.8..-.2 in (0 .5 1), filled.
    Extent quad = extentOf(img, [](Rgb c) { return c.r == 0 && std::abs(c.g - 128) <= 1 && c.b == 255; });
    EXPECT_EQ(quad.minX, int(24 * (.2 + 2) + .5));
    EXPECT_EQ(quad.maxY + 1, int(24 * (2 + 1.8) + .5));
    EXPECT_EQ(quad.count, long(quad.maxX - quad.minX + 1) * (quad.maxY - quad.minY + 1));
    // The line loop is a green outline: its inside stays black.
    glm::ivec2 inside = px2(1.0, .7);
    EXPECT_TRUE(isBlack(at(img, inside.x, inside.y)));
    Extent green = extentOf(img, exactly(0, 255, 0));
    EXPECT_NEAR(green.minX + .5, 24 * (.2 + 2), 2.0);
    EXPECT_NEAR(green.maxX + .5, 24 * (1.8 + 2), 2.0);
    EXPECT_NEAR(green.minY + .5, 24 * (2 - 1.8), 2.0);
    // Three white points of size 5 at y = -1, x = -1.5, -1, -.5: 75 pixels.
    Extent white = extentOf(img, exactly(255, 255, 255));
    EXPECT_EQ(white.count, 3 * 25);
    EXPECT_NEAR((white.minY + white.maxY + 1) / 2.0, 24 * (2 + 1), .5);
    EXPECT_NEAR((white.minX + white.maxX + 1) / 2.0, 24 * (-1 + 2), .5);
}

// ---- tessellation.glib ------------------------------------------------------
// uLevel 6 on a quad patch: a 7 x 7 grid of vertices (u, v) = (i/6, j/6) at
// (2u - 1, 2v - 1, 1 - 2((u-.5)^2 + (v-.5)^2)), coloured (u, v, z/2); lines
// between them and nothing inside the cells.
TEST(GlmanProperties, TessellationLevelSixMakesASevenBySevenGridOfVertices) {
    Image img = rendered("tessellation");
    glm::mat4 mvp = ortho(1.2f) * lookAt({0, -2, 3}, {0, 0, .3f}, {0, 0, 1});
    auto position = [](double u, double v) {
        return glm::vec3(float(2 * u - 1), float(2 * v - 1), float(1 - 2 * ((u - .5) * (u - .5) + (v - .5) * (v - .5))));
    };
    int matched = 0;
    for (int i = 0; i <= 6; ++i)
        for (int j = 0; j <= 6; ++j) {
            double u = i / 6.0, v = j / 6.0;
            glm::vec3 p = position(u, v);
            glm::vec2 q = toPixel(mvp, p);
            double want[3] = {u * 255, v * 255, p.z * .5 * 255};
            if (want[0] + want[1] + want[2] < 40) continue;  // too dark to tell from the background
            int best = 1000;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int x = std::clamp(int(q.x) + dx, 0, kSize - 1), y = std::clamp(int(q.y) + dy, 0, kSize - 1);
                    Rgb c = at(img, x, y);
                    int d = int(std::max({std::abs(c.r - want[0]), std::abs(c.g - want[1]), std::abs(c.b - want[2])}));
                    best = std::min(best, d);
                }
            EXPECT_LE(best, 12) << "vertex " << i << "," << j;
            matched += best <= 12;
        }
    EXPECT_GE(matched, 45);
    // Inside every cell, at least 2 pixels from its four edges and from
    // either diagonal (the tessellator splits each cell one way or the
    // other): background.
    int inside = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            glm::vec2 a = toPixel(mvp, position(i / 6.0, j / 6.0)), b = toPixel(mvp, position((i + 1) / 6.0, j / 6.0)),
                      c = toPixel(mvp, position((i + 1) / 6.0, (j + 1) / 6.0)),
                      d = toPixel(mvp, position(i / 6.0, (j + 1) / 6.0));
            for (auto [fu, fv] : {std::pair{.5, .2}, {.5, .8}, {.2, .5}, {.8, .5}}) {
                glm::vec2 q = toPixel(mvp, position((i + fu) / 6, (j + fv) / 6));
                glm::vec2 centre(std::floor(q.x) + .5f, std::floor(q.y) + .5f);
                double clear = 1e9;
                for (auto [e0, e1] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}, {a, c}, {b, d}})
                    clear = std::min(clear, distanceToSegment(centre, e0, e1));
                if (clear < 2.0) continue;
                ++inside;
                EXPECT_TRUE(isBlack(at(img, int(q.x), int(q.y)))) << "cell " << i << "," << j << " at " << fu << ","
                                                                  << fv;
            }
        }
    EXPECT_GE(inside, 36);  // 54 points qualify at 96x96
}

// ---- clouds.glib ------------------------------------------------------------
// Pixel = (x + 2.2) 96 / 4.4. PointCloud 300 .9: points in the cube +-.9
// around (-1.1, 0), size 2. JitterCloud 6 .9 .5 around (1.1, 0): a 6^3 grid
// of cell centres -.75, -.45, ... .75 (cell .3), each moved at most half a
// cell x .5 = .075: every cyan pixel sits in one of six columns and rows.
TEST(GlmanProperties, CloudsStayInTheirCubeAndTheJitterGrid) {
    Image img = rendered("clouds");
    const double k = 96 / 4.4;
    Extent yellow = extentOf(img, exactly(255, 255, 0));
    EXPECT_GT(yellow.count, 300);
    EXPECT_GE(yellow.minX, int(k * (-2.0 + 2.2)) - 1);
    EXPECT_LE(yellow.maxX, int(k * (-.2 + 2.2)) + 1);
    EXPECT_GE(yellow.minY, int(k * (2.2 - .9)) - 1);
    EXPECT_LE(yellow.maxY, int(k * (2.2 + .9)) + 1);
    // 300 uniform points reach within a tenth of each face.
    EXPECT_LE(yellow.minX, int(k * (-1.82 + 2.2)) + 1);
    EXPECT_GE(yellow.maxX, int(k * (-.38 + 2.2)) - 1);
    long cyan = 0, off = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Rgb c = at(img, x, y);
            if (!(c.r == 0 && c.g == 255 && c.b == 255)) continue;
            ++cyan;
            double wx = (x + .5) / k - 2.2 - 1.1, wy = 2.2 - (y + .5) / k;
            auto nearGrid = [](double w) {
                double best = 1e9;
                for (int i = 0; i < 6; ++i) best = std::min(best, std::abs(w - (-.75 + .3 * i)));
                return best;
            };
            // .075 of jitter, a point of size 2 (one pixel either side, 1/k).
            if (nearGrid(wx) > .075 + 1.5 / k || nearGrid(wy) > .075 + 1.5 / k) ++off;
        }
    EXPECT_GT(cyan, 100);
    EXPECT_EQ(off, 0);
}

// ---- quadbox.glib -----------------------------------------------------------
// Inside the box looking at (1 -.6 1): the +X wall on the left, +Z on the
// right, the floor below, each 0.5 + 0.5 x its inward normal (color.vert).
TEST(GlmanProperties, QuadBoxWallsAreTheirInwardNormals) {
    Image img = rendered("quadbox");
    glm::mat4 mvp = glm::perspective(glm::radians(90.f), 1.f, .1f, 1000.f) *
                    lookAt({0, 0, 0}, {1, -.6f, 1}, {0, 1, 0});
    struct Wall {
        glm::vec3 point, colour;
    } walls[] = {{{2, .5f, .5f}, {0, .5f, .5f}},    // +X wall, inward normal -X
                 {{.5f, .5f, 2}, {.5f, .5f, 0}},    // +Z wall, normal -Z
                 {{1, -2, 1}, {.5f, 1, .5f}}};      // floor, normal +Y
    for (const auto& w : walls) {
        glm::vec2 q = toPixel(mvp, w.point);
        ASSERT_TRUE(q.x >= 0 && q.x < kSize && q.y >= 0 && q.y < kSize);
        Rgb c = at(img, int(q.x), int(q.y));
        EXPECT_NEAR(c.r, w.colour.r * 255, 1) << w.point.x << " " << w.point.y << " " << w.point.z;
        EXPECT_NEAR(c.g, w.colour.g * 255, 1);
        EXPECT_NEAR(c.b, w.colour.b * 255, 1);
    }
}

// ---- skybox.glib ------------------------------------------------------------
// Which face a direction reads: the largest component. The sky pictures are
// each one hue (two shades): px red, nx cyan, py green, ny magenta, pz blue,
// nz yellow.
int faceOf(glm::vec3 d) {
    glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x > 0 ? 0 : 1;
    if (a.y >= a.z) return d.y > 0 ? 2 : 3;
    return d.z > 0 ? 4 : 5;
}
int hueOf(Rgb c) {
    // Shades are 73 on / 20 off and 220 on / 60 off (and blends of one
    // shade of a face): a channel is on when above 0.6 of the strongest.
    int top = std::max({c.r, c.g, c.b});
    bool r = c.r > 0.6 * top, g = c.g > 0.6 * top, b = c.b > 0.6 * top;
    if (r && !g && !b) return 0;
    if (!r && g && b) return 1;
    if (!r && g && !b) return 2;
    if (r && !g && b) return 3;
    if (!r && !g && b) return 4;
    if (r && g && !b) return 5;
    return -1;
}

TEST(GlmanProperties, SkyboxWallsAndMirrorReadTheFaceTheirDirectionsName) {
    Image img = rendered("skybox");
    glm::mat4 turn = rotate(30, 0, 1, 0) * rotate(15, 1, 0, 0);
    glm::mat4 proj = glm::perspective(glm::radians(90.f), 1.f, .1f, 1000.f);
    // The walls (quads at +-10 around the eye): the eye ray through a pixel,
    // back in world space, names the face the quad there shows.
    for (auto [x, y] : {std::pair{48, 48}, {90, 48}, {48, 92}, {60, 10}}) {
        glm::vec3 eyeRay((x + .5f) / kSize * 2 - 1, 1 - (y + .5f) / kSize * 2, -1.f);  // 90 degrees: tan 45 = 1
        glm::vec3 world = glm::transpose(glm::mat3(turn)) * eyeRay;
        EXPECT_EQ(hueOf(at(img, x, y)), faceOf(world)) << "wall pixel " << x << "," << y;
    }
    // The mirror sphere (radius 1 at the turned (0 0 -3)): at its point
    // nearest the eye the reflected ray goes straight back, -centre in eye
    // space, and skybox.frag looks the cube map up with that eye-space vector.
    glm::vec3 centre = glm::vec3(turn * glm::vec4(0, 0, -3, 1));
    glm::vec3 nearest = centre * (1.f - 1.f / glm::length(centre));
    glm::vec2 q = toPixel(proj, nearest);
    EXPECT_EQ(hueOf(at(img, int(q.x), int(q.y))), faceOf(-centre)) << "mirror at " << q.x << "," << q.y;
}

// ---- texture3d.glib ---------------------------------------------------------
// ramp.tex is 4x4x4 with r = 85 x, g = 85 y, b = 85 z: linear, so GL_LINEAR
// inside the texel centres gives r = 85 (4s - .5), g = 85 (4t - .5) exactly,
// and the slices uR .125 and .875 are z texels 0 and 3: b 0 and 255.
TEST(GlmanProperties, Texture3DSlicesAreTheRampsValues) {
    Image img = rendered("texture3d");
    int checked = 0;
    for (int quad = 0; quad < 2; ++quad)
        for (int y = 24; y < 72; ++y)
            for (int x = 0; x < 48; ++x) {
                double s = (x + .5) / 48, t = 1 - (y - 24 + .5) / 48;
                if (s < .125 || s > .875 || t < .125 || t > .875) continue;
                Rgb c = at(img, x + 48 * quad, y);
                ASSERT_NEAR(c.r, 85 * (4 * s - .5), 1.5) << x << "," << y;
                ASSERT_NEAR(c.g, 85 * (4 * t - .5), 1.5) << x << "," << y;
                ASSERT_NEAR(c.b, quad == 0 ? 0 : 255, 1) << x << "," << y;
                ++checked;
            }
    EXPECT_EQ(checked, 2 * 36 * 36);
}

// ---- noise.glib -------------------------------------------------------------
// noise3.frag colours the sphere (sum, .8 sum, 1 - sum): whatever the noise,
// G = .8 R and B = 255 - R; the sum of four octaves centred on .5 with one
// subtracted, halved, is centred on .5. Noise2 on the quad: every channel
// centred on .5.
TEST(GlmanProperties, NoiseSphereFollowsItsFormulaAndBothAreCentred) {
    Image img = rendered("noise");
    long sphere = 0, quad = 0;
    double sumR = 0, quadMean[3] = {0, 0, 0}, quadMin = 255, quadMax = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Rgb c = at(img, x, y);
            if (isBlack(c)) continue;
            if (x >= 48) {
                ++sphere;
                sumR += c.r;
                ASSERT_NEAR(c.g, .8 * c.r, 1.5) << x << "," << y;
                ASSERT_NEAR(c.b, 255 - c.r, 1.5) << x << "," << y;
            } else {
                ++quad;
                quadMean[0] += c.r;
                quadMean[1] += c.g;
                quadMean[2] += c.b;
                quadMin = std::min(quadMin, double(c.r));
                quadMax = std::max(quadMax, double(c.r));
            }
        }
    // Sphere of radius .95 under Ortho -2 2 at 96: about pi (22.8)^2 pixels;
    // the quad 1.9 wide: about 45.6^2.
    EXPECT_NEAR(sphere, M_PI * 22.8 * 22.8, 60);
    EXPECT_NEAR(quad, 45.6 * 45.6, 100);
    EXPECT_NEAR(sumR / sphere / 255, .5, .05);
    for (double m : quadMean) EXPECT_NEAR(m / quad / 255, .5, .05);
    EXPECT_GT(quadMax - quadMin, 40);  // not flat
}

// ---- flat_smooth.glib -------------------------------------------------------
// color.vert colours each vertex 0.5 + 0.5 n. Flat (left) keeps one vertex's
// colour per triangle: every pixel is one of the sphere's vertex colours.
// Smooth (right) blends them: many more colours, red growing to the right.
TEST(GlmanProperties, FlatSphereShowsOnlyVertexColoursSmoothBlendsThem) {
    Image img = rendered("flat_smooth");
    Mesh sphere = makeSphere(.9f, 8, 6);
    std::vector<glm::vec3> vertexColours;
    for (const auto& v : sphere.vertices) vertexColours.push_back((.5f + .5f * glm::normalize(v.normal)) * 255.f);
    std::set<int> flatColours, smoothColours;
    long flatPixels = 0, offVertex = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Rgb c = at(img, x, y);
            if (isBlack(c)) continue;
            int key = (c.r << 16) | (c.g << 8) | c.b;
            if (x < 48) {
                ++flatPixels;
                flatColours.insert(key);
                double best = 1e9;
                for (auto vc : vertexColours)
                    best = std::min(best, double(std::max({std::abs(c.r - vc.r), std::abs(c.g - vc.g),
                                                           std::abs(c.b - vc.b)})));
                offVertex += best > 1.5;
            } else {
                smoothColours.insert(key);
            }
        }
    EXPECT_GT(flatPixels, 1000);
    EXPECT_EQ(offVertex, 0);
    EXPECT_LE(flatColours.size(), vertexColours.size());
    EXPECT_GT(smoothColours.size(), 300u);
    // Along the smooth sphere's equator (row 48), red never falls going right.
    int last = -1, falls = 0;
    for (int x = 48; x < kSize; ++x) {
        Rgb c = at(img, x, 48);
        if (isBlack(c)) continue;
        falls += c.r + 1 < last;
        last = c.r;
    }
    EXPECT_EQ(falls, 0);
}

// ---- all_commands.glib ------------------------------------------------------
// Among everything, LinesAdjacency [0 0 0] [1 0 0] [2 1 0] [3 1 0] through
// linesadj.geom in the current Color 1 1 1: the only pure white is the
// segment (1 0 0)-(2 1 0) and its ticks 30% towards the neighbours, under
// Perspective 50 and LookAt 0 2 9 -> origin. The Background is .1 .1 .2.
TEST(GlmanProperties, AllCommandsBackgroundAndTheLinesAdjacencyPolyline) {
    Image img = rendered("all_commands");
    for (auto [x, y] : {std::pair{1, 1}, {94, 1}, {1, 94}, {94, 94}}) {
        Rgb c = at(img, x, y);
        EXPECT_NEAR(c.r, 25.5, 1);
        EXPECT_NEAR(c.g, 25.5, 1);
        EXPECT_NEAR(c.b, 51, 1);
    }
    glm::mat4 mvp = glm::perspective(glm::radians(50.f), 1.f, .1f, 1000.f) * lookAt({0, 2, 9}, {0, 0, 0}, {0, 1, 0});
    const glm::vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0}};
    glm::vec2 line[4] = {toPixel(mvp, glm::mix(v[1], v[0], .3f)), toPixel(mvp, v[1]), toPixel(mvp, v[2]),
                         toPixel(mvp, glm::mix(v[2], v[3], .3f))};
    long white = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            Rgb c = at(img, x, y);
            if (!(c.r == 255 && c.g == 255 && c.b == 255)) continue;
            ++white;
            glm::vec2 q(x + .5f, y + .5f);
            double d = std::min({distanceToSegment(q, line[0], line[1]), distanceToSegment(q, line[1], line[2]),
                                 distanceToSegment(q, line[2], line[3])});
            EXPECT_LE(d, 1.5) << "white pixel " << x << "," << y << " off the polyline";
        }
    // The far end of the tick towards (3 1 0) is drawn.
    bool end = false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -2; dx <= 0; ++dx) {
            Rgb c = at(img, int(line[3].x) + dx, int(line[3].y) + dy);
            end |= c.r == 255 && c.g == 255 && c.b == 255;
        }
    EXPECT_TRUE(end) << "at " << line[3].x << "," << line[3].y;
    EXPECT_GE(white, long(glm::length(line[2] - line[1])));
}

}  // namespace
