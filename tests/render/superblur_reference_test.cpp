// The seed's superblur and bloom, rendered by Glimmer, against a CPU
// reference in double precision. The calibration scene covers each target
// exactly with its quad, so every superblur tap lands on a texel centre and
// the reference needs no model of texture filtering.
#include <algorithm>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "image/test_images.h"
#include "reference/superblur_reference.h"
#include "render_harness.h"

namespace fs = std::filesystem;
using namespace glimmer;
using namespace glimmer::testing;

namespace {

// Not a power of two and not square, so a swapped axis or an off-by-one
// texel shows.
constexpr int kW = 80, kH = 48;

fs::path calibrationScript() {
    // One folder per process: CTest runs the cases of this file in parallel
    // processes, and one must never read another's half-written files.
    fs::path dir = fs::temp_directory_path() / ("glimmer_calibration_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string err;
    EXPECT_TRUE(writeBmp((dir / "input.bmp").string(), makeNoiseImage(kW, kH, 7), err)) << err;
    std::ofstream(dir / "calibration.glib") << "##OpenGL GLIB\n"
                                               "Ortho -1 1 -1 1\n"
                                               "LookAt 0 0 1  0 0 0  0 1 0\n"
                                               "Texture2D 5 input.bmp\n"
                                               "Texture2D 6 " << kW << " " << kH << "\n"
                                               "Texture2D 8 " << kW << " " << kH << "\n"
                                               "RenderToTexture 6\n"
                                               "Clear\n"
                                               "Vertex superblur.vert\n"
                                               "Fragment superblur.frag\n"
                                               "Program SuperBlur  uHalfSize <0 0 11>  ImageUnit 5\n"
                                               "QuadXY 0 1\n"
                                               "RenderToTexture 8\n"
                                               "Clear\n"
                                               "Vertex bloom.vert\n"
                                               "Fragment bloom.frag\n"
                                               "Program Bloom  BlurUnit 6  ImageUnit 5  uAdd <0. 0. 4.>\n"
                                               "QuadXY 0 1\n"
                                               "RenderToTexture\n";
    return dir / "calibration.glib";
}

struct Case {
    std::string backend;
    int halfSize;
    double add;
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    std::string b = info.param.backend;
    for (auto& c : b)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return b + "_half" + std::to_string(info.param.halfSize) + "_add" + std::to_string(int(info.param.add));
}

std::vector<Case> allCases() {
    std::vector<Case> cases;
    for (const auto& b : testBackends())
        for (int h : {0, 1, 5, 11})
            for (double a : {0.0, 1.0, 4.0}) cases.push_back({b, h, a});
    return cases;
}

class SuperblurBloom : public ::testing::TestWithParam<Case> {};

TEST_P(SuperblurBloom, MatchesDoublePrecisionReferenceWithinOneStep) {
    const Case& c = GetParam();
    fs::path script = calibrationScript();
    Rendered r = renderScript(c.backend, script.string(),
                              {"uHalfSize=" + std::to_string(c.halfSize), "uAdd=" + std::to_string(c.add)}, {5, 6, 8});
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.units[6].width, kW);
    ASSERT_EQ(r.units[8].height, kH);

    RgbImage input = toRgb(r.units[5]);
    Image expectedBlur = quantizeToRgba8(superblurReference(input, c.halfSize));
    Difference blur = compareRgb(r.units[6], expectedBlur);
    EXPECT_LE(blur.maxSteps, 1) << "blur off by " << blur.maxSteps << " steps at " << blur.x << "," << blur.y;

    // The blur reaches the bloom pass through an RGBA8 target, so the bloom
    // reference starts from the bytes that target holds: a value that lands
    // on a rounding boundary may round either way, and uAdd would multiply
    // that one step into four.
    Image expectedBloom = quantizeToRgba8(bloomReference(input, toRgb(r.units[6]), c.add));
    Difference bloom = compareRgb(r.units[8], expectedBloom);
    EXPECT_LE(bloom.maxSteps, 1) << "bloom off by " << bloom.maxSteps << " steps at " << bloom.x << "," << bloom.y;
}

INSTANTIATE_TEST_SUITE_P(Calibration, SuperblurBloom, ::testing::ValuesIn(allCases()), caseName);

// uHalfSize 0 still blurs: `uHalfSize | 01` makes it 1, a 3x3 kernel.
TEST(SuperblurExtremes, HalfSizeZeroStillBlursThreeByThree) {
    RgbImage dot;
    dot.width = 9;
    dot.height = 9;
    dot.rgb.assign(9 * 9 * 3, 0.0);
    dot.rgb[(4 * 9 + 4) * 3] = 1.0;
    RgbImage out = superblurReference(dot, 0);
    EXPECT_GT(out.at(3, 3, 0), 0.0);
    EXPECT_GT(out.at(5, 5, 0), 0.0);
    EXPECT_EQ(out.at(2, 4, 0), 0.0);
    EXPECT_EQ(out.at(4, 6, 0), 0.0);
}

// uAdd 4 saturates: white where image + 4 x blur passes 1.
TEST(SuperblurExtremes, AddFourSaturatesBrightPixels) {
    const auto backends = testBackends();
    fs::path script = calibrationScript();
    Rendered r = renderScript(backends.front(), script.string(), {"uHalfSize=11", "uAdd=4"}, {6, 8});
    ASSERT_TRUE(r.ok) << r.error;
    long saturated = 0;
    for (size_t i = 0; i < r.units[8].u8.size(); i += 4) saturated += r.units[8].u8[i] == 255;
    // Noise averages to about 0.5, so 4 x blur alone is about 2: nearly every pixel clips.
    EXPECT_GT(saturated, long(kW * kH * 9 / 10));
}

// The two CPU backends run the same llvmpipe: the pictures must agree to the bit.
TEST(Backends, OsMesaAndEglSurfacelessGiveIdenticalPixels) {
    // Only meaningful where both CPU backends are under test (the default,
    // and so always in CI); a GPU run sets GLIMMER_TEST_BACKENDS=egl-device.
    auto list = testBackends();
    if (std::count(list.begin(), list.end(), "osmesa") == 0 || std::count(list.begin(), list.end(), "egl-surfaceless") == 0)
        GTEST_SKIP() << "GLIMMER_TEST_BACKENDS does not name both osmesa and egl-surfaceless";
    fs::path script = calibrationScript();
    Rendered a = renderScript("osmesa", script.string(), {"uHalfSize=5", "uAdd=2"}, {6, 8});
    ASSERT_TRUE(a.ok) << a.error;
    Rendered b = renderScript("egl-surfaceless", script.string(), {"uHalfSize=5", "uAdd=2"}, {6, 8});
    ASSERT_TRUE(b.ok) << b.error;
    EXPECT_EQ(a.units[6].u8, b.units[6].u8);
    EXPECT_EQ(a.units[8].u8, b.units[8].u8);
    EXPECT_EQ(a.screen.u8, b.screen.u8);
}

}  // namespace
