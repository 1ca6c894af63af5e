// The seed's superblur and bloom, rendered by Glimmer, against a CPU
// reference in double precision. The calibration scene covers each target
// exactly with its quad, so every superblur tap lands on a texel centre and
// the reference needs no model of texture filtering.
#include <algorithm>
#include <cstdio>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "image/test_images.h"
#include "bloom/superblur_reference.h"
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
    // Removed when the process ends (a static's destructor), so no
    // glimmer_calibration_<pid> folder is left in the temp folder.
    struct Folder {
        fs::path path = fs::temp_directory_path() / ("glimmer_calibration_" + std::to_string(::getpid()));
        ~Folder() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    };
    static Folder folder;
    const fs::path& dir = folder.path;
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

// The cases are fixed; the backends each case runs on are read inside the
// test (testBackends()), so GLIMMER_TEST_BACKENDS=egl-device runs these same
// 12 cases on the GPU, and a backend that is not there fails them, named.
struct Case {
    int halfSize;
    double add;
};

void PrintTo(const Case& c, std::ostream* os) { *os << "uHalfSize " << c.halfSize << ", uAdd " << c.add; }

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    return "half" + std::to_string(info.param.halfSize) + "_add" + std::to_string(int(info.param.add));
}

std::vector<Case> allCases() {
    std::vector<Case> cases;
    for (int h : {0, 1, 5, 11})
        for (double a : {0.0, 1.0, 4.0}) cases.push_back({h, a});
    return cases;
}

class SuperblurBloom : public ::testing::TestWithParam<Case> {};

// Tolerances, derived (the same on llvmpipe and on a GPU):
// - Blur target against the double reference rounded to nearest: at most 1
//   step. The shader's float sum is off by far less than 0.01 step (529 taps
//   at 2^-24 relative error), and an RGBA8 target may round to nearest or
//   truncate: round(x) - floor(x - e) < 1.5 + e, an integer, so <= 1.
// - Bloom target against image + uAdd x (the bytes the blur target holds),
//   rounded: at most 1 step, for the same reason. Starting from the stored
//   bytes keeps the blur target's rounding out of this comparison.
// - Bloom target against the all-double chain, image + uAdd x blur, rounded:
//   the stored blur is within 1 step (exclusive) of the exact blur whichever
//   way the target rounds, so uAdd x blur is within uAdd steps; the output
//   target adds under 1 more, rounding the reference under 0.5 more:
//   |diff| < 1.5 + uAdd, an integer, so <= 1 + uAdd (uAdd is whole here).
//   This one ties the picture to the reference with nothing taken from the
//   renderer but the input image.
TEST_P(SuperblurBloom, MatchesDoublePrecisionReferenceWithinOneStep) {
    const Case& c = GetParam();
    fs::path script = calibrationScript();
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE("backend " + backend);
        Rendered r = renderScript(backend, script.string(),
                                  {"uHalfSize=" + std::to_string(c.halfSize), "uAdd=" + std::to_string(c.add)},
                                  {5, 6, 8});
        if (!r.ok) {
            ADD_FAILURE() << "backend " << backend << " did not render: " << r.error;
            continue;
        }
        ASSERT_EQ(r.units[6].width, kW);
        ASSERT_EQ(r.units[8].height, kH);

        RgbImage input = toRgb(r.units[5]);
        RgbImage exactBlur = superblurReference(input, c.halfSize);
        Difference blur = compareRgb(r.units[6], quantizeToRgba8(exactBlur));
        EXPECT_LE(blur.maxSteps, 1) << backend << ": blur off by " << blur.maxSteps << " steps at " << blur.x << ","
                                    << blur.y;

        Image expectedBloom = quantizeToRgba8(bloomReference(input, toRgb(r.units[6]), c.add));
        Difference bloom = compareRgb(r.units[8], expectedBloom);
        EXPECT_LE(bloom.maxSteps, 1) << backend << ": bloom off by " << bloom.maxSteps << " steps at " << bloom.x
                                     << "," << bloom.y;

        Difference chain = compareRgb(r.units[8], quantizeToRgba8(bloomReference(input, exactBlur, c.add)));
        EXPECT_LE(chain.maxSteps, 1 + int(c.add))
            << backend << ": bloom off the all-double chain by " << chain.maxSteps << " steps at " << chain.x << ","
            << chain.y;
        std::printf("[ figures  ] %s half %d add %g: blur %d, bloom %d, chain %d steps (max)\n", backend.c_str(),
                    c.halfSize, c.add, blur.maxSteps, bloom.maxSteps, chain.maxSteps);
    }
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

// The two CPU backends run the same llvmpipe: the pictures must agree to the
// bit. This test names its backends itself, whatever GLIMMER_TEST_BACKENDS
// says: Mesa is installed wherever the suite runs (test_glman and test_cli
// use OSMesa too), so on a GPU machine it runs, and fails if either is absent.
TEST(Backends, OsMesaAndEglSurfacelessGiveIdenticalPixels) {
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
