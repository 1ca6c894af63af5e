// Rendered pictures checked against what the CPU works out independently:
// a texture lookup on a QuadXY, a sphere's silhouette under a known Ortho,
// cube-map lookups along the six axes, and the statistics of Noise2.
#include <cmath>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "glman_harness.h"

using namespace glimmer;
using namespace glimmer::glmantest;

namespace {

namespace fs = std::filesystem;

// OpenGL's GL_LINEAR with GL_REPEAT on the CPU: texture coordinates (s, t),
// t = 0 at the bottom row of the picture (the image's last row).
double bilinear(const Image& tex, double s, double t, int c) {
    auto at = [&](int i, int j) {
        i = ((i % tex.width) + tex.width) % tex.width;
        j = ((j % tex.height) + tex.height) % tex.height;
        return double(pixel(tex, i, tex.height - 1 - j)[c]);
    };
    double u = s * tex.width - .5, v = t * tex.height - .5;
    int i = int(std::floor(u)), j = int(std::floor(v));
    double fu = u - i, fv = v - j;
    return (1 - fu) * (1 - fv) * at(i, j) + fu * (1 - fv) * at(i + 1, j) + (1 - fu) * fv * at(i, j + 1) +
           fu * fv * at(i + 1, j + 1);
}

// QuadXY 0 1 fills Ortho -1 1 -1 1 exactly, so pixel (x, y) (y from the top)
// samples s = (x + .5) / 96, t = 1 - (y + .5) / 96 of the 3x3 texture.
TEST(GlmanCpu, QuadXYShowsTheTextureAsOpenGLSamplesIt) {
    auto r = glimmer::testing::renderScript("osmesa", script("quad_texture"), {}, {});
    ASSERT_TRUE(r.ok) << r.error;
    Image tex;
    std::string why;
    ASSERT_TRUE(loadImage(dataDir() + "/grid3.bmp", tex, why)) << why;
    ASSERT_EQ(tex.width, 3);
    int worst = 0;
    for (int y = 0; y < 96; y += 5)
        for (int x = 0; x < 96; x += 5)
            for (int c = 0; c < 3; ++c) {
                double want = bilinear(tex, (x + .5) / 96, 1 - (y + .5) / 96, c);
                int d = int(std::abs(pixel(r.screen, x, y)[c] - want) + .5);
                worst = std::max(worst, d);
                ASSERT_LE(d, 2) << "pixel " << x << "," << y << " channel " << c;
            }
    // And the texel centres hold the texel's own colour, top row on top.
    EXPECT_GT(pixel(r.screen, 16, 16)[0], 240);  // red, top left
    EXPECT_LT(pixel(r.screen, 16, 16)[1], 15);
    EXPECT_LT(pixel(r.screen, 80, 80)[0], 15);   // black, bottom right
}

// A unit sphere under Ortho -2 2 -2 2 at 96x96: radius 24 pixels, centred.
TEST(GlmanCpu, SphereSilhouetteRadiusUnderOrtho) {
    auto r = glimmer::testing::renderScript("osmesa", script("sphere_ortho"), {}, {});
    ASSERT_TRUE(r.ok) << r.error;
    long lit = 0;
    double sx = 0, sy = 0;
    int widest = 0;
    for (int y = 0; y < r.screen.height; ++y) {
        int row = 0;
        for (int x = 0; x < r.screen.width; ++x) {
            if (pixel(r.screen, x, y)[0] > 128) {
                ++lit;
                ++row;
                sx += x + .5;
                sy += y + .5;
            }
        }
        widest = std::max(widest, row);
    }
    ASSERT_GT(lit, 0);
    // 40 slices: the silhouette is a 40-gon of circumradius 24, area
    // 20 r^2 sin(2 pi / 40), so the equivalent radius is 23.9.
    double radius = std::sqrt(double(lit) / M_PI);
    EXPECT_NEAR(radius, 24.0 * std::sqrt(20 * std::sin(2 * M_PI / 40) / M_PI), 0.5);
    EXPECT_NEAR(widest, 48, 1);
    EXPECT_NEAR(sx / double(lit), 48.0, 0.5);
    EXPECT_NEAR(sy / double(lit), 48.0, 0.5);
}

// A folder of its own with six solid-colour faces, the shaders and a script
// whose fragment shader looks along one axis per cell of a 3 x 2 grid.
class CubeAxes : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("glimmer_cube_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const char* f : {"pass.vert", "cubeaxes.frag"}) fs::copy_file(dataDir() + "/" + f, dir / f);
        const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
        for (int i = 0; i < 6; ++i) {
            Image img = Image::rgba8(8, 8);
            for (size_t k = 0; k < img.u8.size(); k += 4) {
                img.u8[k] = colours[i][0];
                img.u8[k + 1] = colours[i][1];
                img.u8[k + 2] = colours[i][2];
                img.u8[k + 3] = 255;
            }
            std::string why;
            ASSERT_TRUE(writeBmp((dir / (std::string(names[i]) + ".bmp")).string(), img, why)) << why;
        }
        std::ofstream(dir / "axes.glib") << "WindowSize 96 96\nOrtho -1 1 -1 1\n"
                                            "CubeMap 4 px.bmp nx.bmp py.bmp ny.bmp pz.bmp nz.bmp\n"
                                            "Vertex pass.vert\nFragment cubeaxes.frag\nProgram Axes uCube 4\n"
                                            "QuadXY 0 1\n";
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
    const std::uint8_t colours[6][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255},
                                        {255, 255, 0}, {0, 255, 255}, {255, 0, 255}};
};

TEST_F(CubeAxes, EachAxisReadsItsOwnFace) {
    auto r = glimmer::testing::renderScript("osmesa", (dir / "axes.glib").string(), {}, {});
    ASSERT_TRUE(r.ok) << r.error;
    // Cells: bottom row +x -x +y, top row -y +z -z (cubeaxes.frag); 32 x 48
    // pixels each, rows counted from the top of the picture.
    for (int i = 0; i < 6; ++i) {
        int col = i % 3, row = i / 3;
        int x = 32 * col + 16, y = row == 0 ? 72 : 24;
        const std::uint8_t* got = pixel(r.screen, x, y);
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(int(got[c]), int(colours[i][c])) << "face " << i << " channel " << c;
    }
}

// One pixel per texel of Noise2D 64: the statistics of the picture are those
// of glman's noise: every channel centred on 0.5, each next octave with half
// the spread of the one before.
TEST(GlmanCpu, Noise2OnAFullScreenQuadHasGlmansStatistics) {
    auto r = glimmer::testing::renderScript("osmesa", script("noise2_stats"), {}, {});
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.screen.width, 64);
    double mean[3] = {0, 0, 0}, var[3] = {0, 0, 0};
    const double n = 64.0 * 64.0;
    for (size_t k = 0; k < r.screen.u8.size(); k += 4)
        for (int c = 0; c < 3; ++c) mean[c] += r.screen.u8[k + size_t(c)] / 255.0 / n;
    for (size_t k = 0; k < r.screen.u8.size(); k += 4)
        for (int c = 0; c < 3; ++c) var[c] += std::pow(r.screen.u8[k + size_t(c)] / 255.0 - mean[c], 2) / n;
    double sd[3];
    for (int c = 0; c < 3; ++c) {
        sd[c] = std::sqrt(var[c]);
        EXPECT_NEAR(mean[c], 0.5, 0.01) << "channel " << c;
    }
    EXPECT_NEAR(sd[0], 0.125, 0.01);
    EXPECT_NEAR(sd[1] / sd[0], 0.5, 0.05);
    EXPECT_NEAR(sd[2] / sd[1], 0.5, 0.05);
    // Not a flat colour: texels differ.
    EXPECT_GT(sd[2], 0.02);
}

}  // namespace
