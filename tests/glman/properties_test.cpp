// The glman pictures that golden_test.cpp only compares with earlier output,
// each checked for at least one property worked out here, independently of
// the renderer: where a shape must land (the script's camera applied by hand
// with GLM), the colour a face must have (the shader's formula), how many
// vertices a tessellation makes, the statistics of noise, which cube-map face
// an axis reads. A picture that is wrong but stable fails here.
#include "glman_properties.h"

using namespace glimmer;
using namespace glimmer::glmantest;

namespace {

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

}  // namespace
