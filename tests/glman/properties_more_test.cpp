// The glman pictures that golden_test.cpp only compares with earlier output,
// each checked for at least one property worked out here, independently of
// the renderer: where a shape must land (the script's camera applied by hand
// with GLM), the colour a face must have (the shader's formula), how many
// vertices a tessellation makes, the statistics of noise, which cube-map face
// an axis reads. A picture that is wrong but stable fails here.
// (The second half: quadbox, skybox, texture3d, noise, flat_smooth, all_commands.)
#include "glman_properties.h"

using namespace glimmer;
using namespace glimmer::glmantest;

namespace {

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
