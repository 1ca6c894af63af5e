// Settings to try, verdicts, and the comparison of real pixels.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "grade/grading.h"

namespace glimmer {
namespace {

Image gradient(int w, int h, int shift = 0) {
    Image p = Image::rgba8(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* t = &p.u8[(size_t(y) * size_t(w) + size_t(x)) * 4];
            t[0] = std::uint8_t(std::clamp(x + shift, 0, w - 1) * 255 / (w - 1));
            t[1] = std::uint8_t(((x + shift) / 8 + y / 8) % 2 * 200);
            t[2] = 40;
            t[3] = 255;
        }
    return p;
}

TEST(Grading, SlidersGiveDefaultsThenEachEnd) {
    auto s = settingsFromSliders({{"uA", 0, 0.5, 1}, {"uB", 1, 1, 4}});
    ASSERT_EQ(s.size(), 4u);  // uB's min is its default: not tried twice
    EXPECT_EQ(settingLabel(s[0]), "defaults");
    EXPECT_EQ(settingLabel(s[1]), "uA=0");
    EXPECT_EQ(settingLabel(s[2]), "uA=1");
    EXPECT_EQ(settingLabel(s[3]), "uB=4");
    EXPECT_EQ(settingsFromSliders({{"uA", 0, 0.5, 1}, {"uB", 1, 2, 4}}, 3).size(), 3u);
}

// A solution with many sliders is graded at 16 settings, as docs/teaching.md
// tells teachers: the defaults, then the first sliders' ends in order.
TEST(Grading, ManySlidersGiveSixteenSettings) {
    std::vector<Slider> sliders;
    for (int k = 0; k < 10; ++k) sliders.push_back({"u" + std::to_string(k), 0, 0.5, 1});  // 21 settings possible
    auto s = settingsFromSliders(sliders);
    ASSERT_EQ(s.size(), 16u);
    EXPECT_EQ(settingLabel(s[15]), "u7=0");
}

TEST(Grading, VaryGivesItsValues) {
    std::vector<Setting> s;
    std::string error;
    ASSERT_TRUE(settingsFromVary({"uA=0.25,0.75", "uB=3"}, s, error));
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(settingLabel(s[1]), "uA=0.25");
    EXPECT_EQ(settingLabel(s[3]), "uB=3");
    EXPECT_FALSE(settingsFromVary({"uA"}, s, error));
    EXPECT_EQ(error, "--vary 'uA' is not NAME=V1,V2,...");
    EXPECT_FALSE(settingsFromVary({"uA=,"}, s, error));
    EXPECT_EQ(error, "--vary 'uA=,' gives no values");
}

TEST(Grading, TheSamePictureIsIdenticalAndAShiftedOneIsClose) {
    Image a = gradient(32, 32), b = gradient(32, 32, 1);
    Comparison same = comparePictures(a, a);
    EXPECT_TRUE(std::isinf(same.psnr));
    EXPECT_DOUBLE_EQ(same.ssim, 1.0);
    EXPECT_FALSE(same.blank);
    Comparison shifted = comparePictures(b, a);
    EXPECT_LT(shifted.ssim, 1.0);
    EXPECT_GT(shifted.ssim, 0.5);
    Image blank = Image::rgba8(32, 32);
    Comparison c = comparePictures(blank, a);
    EXPECT_TRUE(c.blank);
    EXPECT_LT(c.ssim, 0.1);
    Comparison sizes = comparePictures(gradient(16, 16), a);
    EXPECT_EQ(sizes.ssim, 0.0);
    EXPECT_EQ(sizes.psnr, 0.0);
}

// Grading compares bytes: a float picture (what an .hdr or .exr loads as) is
// not compared, whichever side it is on, even when its values are the bytes'.
TEST(Grading, AFloatPictureIsNotComparedAsBytes) {
    Image bytes = gradient(32, 32);
    Image floats = Image::rgbaF32(32, 32);
    for (size_t i = 0; i < bytes.u8.size(); ++i) floats.f32[i] = float(bytes.u8[i]) / 255.f;
    for (auto [student, solution] : {std::pair{&floats, &bytes}, std::pair{&bytes, &floats}}) {
        Comparison c = comparePictures(*student, *solution);
        EXPECT_EQ(c.psnr, 0.0);
        EXPECT_EQ(c.ssim, 0.0);
        EXPECT_FALSE(c.blank);
    }
    // All black as floats against a solution that is not one colour: not "blank" either.
    EXPECT_FALSE(blankAgainst(Image::rgbaF32(32, 32), bytes));
}

TEST(Grading, TheDifferencePictureShowsSmallErrorsFourTimes) {
    Image a = Image::rgba8(1, 1), b = Image::rgba8(1, 1);
    a.u8 = {10, 200, 0, 255};
    b.u8 = {12, 100, 0, 255};
    Image d = differencePicture(a, b);
    EXPECT_EQ(d.u8, (std::vector<std::uint8_t>{8, 255, 0, 255}));
}

TEST(Grading, ThumbnailsAverageBoxes) {
    Image p = Image::rgba8(4, 2);
    for (size_t i = 0; i < p.u8.size(); i += 4) p.u8[i] = (i / 4) % 2 ? 200 : 100;
    Image t = thumbnail(p, 2);
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.height, 1);
    EXPECT_EQ(t.u8[0], 150);
}

// A box is rows as well as columns: horizontal stripes of 100 and 200,
// one pixel tall, are 150 in a thumbnail of half the height (issue 40's
// sampled mutant grading.cpp:148 took each box's first row only: 100).
TEST(Grading, ThumbnailsAverageTheRowsOfABoxToo) {
    Image p = Image::rgba8(2, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 2; ++x) p.u8[(size_t(y) * 2 + size_t(x)) * 4] = y % 2 ? 200 : 100;
    Image t = thumbnail(p, 2);
    ASSERT_EQ(t.width, 1);
    ASSERT_EQ(t.height, 2);
    EXPECT_EQ(t.u8[0], 150);
    EXPECT_EQ(t.u8[4], 150);
}

// The report's thumbnails (grading.h: thumbnail) show the picture: each
// pixel the average of its own box, row by row. Four quadrants of four
// colours, 200x96 into 50x24, boxes of 4x4 that never straddle two (issue
// 40's sampled mutant grading.cpp:152 read row y at y + width, and the
// bottom half of every thumbnail showed the top's colours).
TEST(Grading, AThumbnailShowsEachQuadrantOfItsPictureWhereItIs) {
    const std::uint8_t colours[4][4] = {{250, 0, 0, 255}, {0, 250, 0, 255}, {0, 0, 250, 255}, {120, 60, 30, 255}};
    auto quadrant = [](int x, int y, int w, int h) { return (x < w / 2 ? 0 : 1) + (y < h / 2 ? 0 : 2); };
    Image p = Image::rgba8(200, 96);
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 200; ++x)
            for (int c = 0; c < 4; ++c) p.u8[(size_t(y) * 200 + size_t(x)) * 4 + size_t(c)] = colours[quadrant(x, y, 200, 96)][c];
    Image t = thumbnail(p, 50);
    ASSERT_EQ(t.width, 50);
    ASSERT_EQ(t.height, 24);
    long wrong = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 50; ++x)
            for (int c = 0; c < 4; ++c)
                wrong += t.u8[(size_t(y) * 50 + size_t(x)) * 4 + size_t(c)] != colours[quadrant(x, y, 50, 24)][c];
    EXPECT_EQ(wrong, 0);
}

TEST(Grading, VerdictsFollowTheThresholds) {
    Thresholds t;
    size_t worst = 9;
    Comparison perfect{INFINITY, 1.0, false}, close{28, 0.9, false}, far{12, 0.3, false}, blank{10, 0.02, true};
    Verdict v = judge({perfect, perfect}, {}, t, worst);
    EXPECT_EQ(v.kind, "pass");
    EXPECT_EQ(v.score, 100);
    EXPECT_EQ(v.notes, "");
    v = judge({perfect, close, perfect}, {}, t, worst);
    EXPECT_EQ(v.kind, "look");
    EXPECT_EQ(worst, 1u);
    EXPECT_EQ(v.score, 90);
    EXPECT_EQ(v.notes, "SSIM 0.900, PSNR 28.0 dB at the worst setting");
    v = judge({perfect, far}, {}, t, worst);  // right at the defaults is not enough
    EXPECT_EQ(v.kind, "wrong");
    EXPECT_EQ(v.score, 30);
    v = judge({blank}, {}, t, worst);
    EXPECT_EQ(v.kind, "wrong");
    EXPECT_EQ(v.notes, "the picture is a single colour");
    v = judge({perfect}, {"uPower"}, t, worst);
    EXPECT_EQ(v.kind, "look");
    EXPECT_EQ(v.notes, "lacks the solution's uniform uPower");
    EXPECT_EQ(judge({}, {}, t, worst).kind, "error");
}

// Issue 26: the pass rule is SSIM and PSNR, both. A picture uniformly
// brighter than the solution keeps its structure (SSIM high) but is 20 dB
// away: a person must look at it, it does not pass.
TEST(Grading, ThePassNeedsBothSsimAndPsnr) {
    Thresholds t;
    size_t worst = 9;
    EXPECT_EQ(judge({{30, 0.95, false}}, {}, t, worst).kind, "pass");  // both exactly at the thresholds
    Verdict v = judge({{INFINITY, 1.0, false}, {29.9, 0.99, false}}, {}, t, worst);
    EXPECT_EQ(v.kind, "look");
    EXPECT_EQ(v.notes, "SSIM 0.990, PSNR 29.9 dB at the worst setting");
    EXPECT_EQ(judge({{29.99, 1.0, false}}, {}, t, worst).kind, "look");

    Image solution = gradient(64, 64), brighter = solution;
    for (size_t i = 0; i < brighter.u8.size(); ++i)
        if (i % 4 != 3) brighter.u8[i] = std::uint8_t(std::min(255, brighter.u8[i] + 25));
    Comparison c = comparePictures(brighter, solution);
    ASSERT_GE(c.ssim, t.passSsim);  // what makes the picture a test of the PSNR half
    EXPECT_NEAR(c.psnr, 20.2, 0.3);  // 25 of 255 on most channels: about 20 log10(255 / 25) dB
    EXPECT_EQ(judge({c}, {}, t, worst).kind, "look");
}

// A look needs the picture within reach too: PSNR >= 18 dB (an RMS error of
// 32 levels) at every setting. SSIM of the luma forgives brightness over flat
// regions: in the generated class of tools/grading-class.py a submission
// painted for the default setting (no slider read by a shader) kept SSIM
// 0.754 at uThreshold=0.1, 13.6 dB from the solution, and was a "look".
TEST(Grading, ALookNeedsThePictureWithinAnEighthOfTheRange) {
    Thresholds t;
    size_t worst = 9;
    Comparison perfect{INFINITY, 1.0, false};
    Verdict v = judge({perfect, {13.6, 0.754, false}}, {}, t, worst);
    EXPECT_EQ(v.kind, "wrong");
    EXPECT_EQ(v.score, 75);
    EXPECT_EQ(worst, 1u);
    EXPECT_EQ(v.notes, "SSIM 0.754, PSNR 13.6 dB at the worst setting");
    EXPECT_EQ(judge({perfect, {18, 0.754, false}}, {}, t, worst).kind, "look");    // exactly at the threshold
    EXPECT_EQ(judge({perfect, {17.9, 0.99, false}}, {}, t, worst).kind, "wrong");  // however close by SSIM
    // Every setting counts, not only the one with the worst SSIM.
    EXPECT_EQ(judge({{17, 0.99, false}, {25, 0.8, false}}, {}, t, worst).kind, "wrong");
    Thresholds lenient = t;
    lenient.lookPsnr = 10;  // --look-psnr 10
    EXPECT_EQ(judge({perfect, {13.6, 0.754, false}}, {}, lenient, worst).kind, "look");

    // On pictures: 20 levels brighter everywhere is still worth a look (about
    // 22 dB), 45 levels brighter is wrong (about 15 dB), SSIM near 1 for both.
    Image solution = gradient(64, 64);
    for (int levels : {20, 45}) {
        Image brighter = solution;
        for (size_t i = 0; i < brighter.u8.size(); ++i)
            if (i % 4 != 3) brighter.u8[i] = std::uint8_t(std::min(255, brighter.u8[i] + levels));
        Comparison c = comparePictures(brighter, solution);
        ASSERT_GE(c.ssim, t.lookSsim) << levels;
        EXPECT_EQ(judge({c}, {}, t, worst).kind, levels == 20 ? "look" : "wrong") << levels << " levels: " << c.psnr << " dB";
    }
}

// Issue 29: what a mean misses. A 4x4 patch 40 levels off in a 64x64
// gradient is 16 of 4096 pixels (0.39%) off by more than kLocalLevels and
// one tile far below the rest, while SSIM and PSNR alone would pass it;
// 24 levels is not "more than" 24. The verdict is "look", the setting with
// the local error the one shown, and its notes say where.
TEST(Grading, ALocalErrorIsCountedAndMakesAPassALook) {
    Image solution = gradient(64, 64), patched = solution, edge = solution;
    for (int y = 40; y < 44; ++y)
        for (int x = 40; x < 44; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                const size_t i = (size_t(y) * 64 + size_t(x)) * 4 + size_t(ch);
                patched.u8[i] = std::uint8_t(std::min(255, solution.u8[i] + 40));
                edge.u8[i] = std::uint8_t(std::min(255, solution.u8[i] + 24));
            }
    Comparison c = comparePictures(patched, solution);
    EXPECT_DOUBLE_EQ(c.offShare, 16.0 / 4096.0);
    EXPECT_LT(c.worstTile, 0.99);  // an offset: SSIM is kind to it (0.978), the count is not
    EXPECT_DOUBLE_EQ(comparePictures(edge, solution).offShare, 0.0);
    EXPECT_DOUBLE_EQ(comparePictures(solution, solution).offShare, 0.0);
    EXPECT_DOUBLE_EQ(comparePictures(solution, solution).worstTile, 1.0);
    Thresholds t;
    size_t worst = 9;
    Comparison whole{INFINITY, 1.0, false};
    Comparison local = c;
    local.ssim = 0.99;  // as a mean would have it
    local.psnr = 40;
    Verdict v = judge({whole, local}, {}, t, worst);
    EXPECT_EQ(v.kind, "look");
    EXPECT_EQ(worst, 1u);
    EXPECT_EQ(v.notes, "a local error: 0.39% of the pixels off by more than 24 levels, the worst 32x32 tile at SSIM " +
                           fmt::format("{:.3f}", c.worstTile));
    EXPECT_EQ(judge({whole, whole}, {}, t, worst).kind, "pass");
}

// Issue 26: a single-colour picture is wrong even where its SSIM would be
// close enough to look at: a grey canvas against a grey solution with four
// small bright squares.
TEST(Grading, ABlankPictureIsWrongEvenWhenItsSsimLooksClose) {
    Thresholds t;
    size_t worst = 9;
    Verdict v = judge({{15, 0.8, true}}, {}, t, worst);
    EXPECT_EQ(v.kind, "wrong");
    EXPECT_EQ(v.notes, "the picture is a single colour");
    EXPECT_EQ(v.score, 80);

    Image solution = Image::rgba8(64, 64), grey = Image::rgba8(64, 64);
    for (size_t i = 0; i < solution.u8.size(); ++i) solution.u8[i] = grey.u8[i] = i % 4 == 3 ? 255 : 128;
    for (int y = 0; y < 64; ++y)  // four bright 4x4 squares, one in each quarter
        for (int x = 0; x < 64; ++x)
            if (x % 32 >= 14 && x % 32 < 18 && y % 32 >= 14 && y % 32 < 18) solution.u8[(size_t(y) * 64 + size_t(x)) * 4] = 255;
    Comparison c = comparePictures(grey, solution);
    EXPECT_TRUE(c.blank);
    ASSERT_GE(c.ssim, t.lookSsim);  // close by SSIM alone
    ASSERT_LT(c.ssim, t.passSsim);
    EXPECT_EQ(judge({c}, {}, t, worst).kind, "wrong");
}

// Blank means "one colour where the solution is not": a solution that is
// one colour itself (a script that only clears) matched exactly passes; a
// picture that changes only in blue is not one colour.
TEST(Grading, BlankMeansOneColourWhereTheSolutionIsNot) {
    Image black = Image::rgba8(16, 16);
    for (size_t i = 3; i < black.u8.size(); i += 4) black.u8[i] = 255;
    Comparison same = comparePictures(black, black);
    EXPECT_FALSE(same.blank);
    Thresholds t;
    size_t worst = 9;
    EXPECT_EQ(judge({same}, {}, t, worst).kind, "pass");
    Image blues = black;
    for (size_t p = 0; p < 16 * 16; ++p) blues.u8[p * 4 + 2] = std::uint8_t(p);
    EXPECT_FALSE(comparePictures(blues, gradient(16, 16)).blank);
    EXPECT_TRUE(comparePictures(black, gradient(16, 16)).blank);
}

TEST(Grading, TheScoreIsClampedToZeroForANegativeSsim) {
    Thresholds t;
    size_t worst = 9;
    Verdict v = judge({{5, -0.2, false}}, {}, t, worst);
    EXPECT_EQ(v.score, 0);
    EXPECT_EQ(v.kind, "wrong");
    EXPECT_EQ(v.notes, "SSIM -0.200, PSNR 5.0 dB at the worst setting");
}

TEST(Grading, VaryGivesAtMost64Settings) {
    std::vector<Setting> s;
    std::string error, values = "uA=0";
    for (int k = 1; k < 63; ++k) values += "," + std::to_string(k);
    ASSERT_TRUE(settingsFromVary({values}, s, error)) << error;  // the defaults and 63 values
    EXPECT_EQ(s.size(), 64u);
    EXPECT_FALSE(settingsFromVary({values + ",63"}, s, error));
    EXPECT_EQ(error, "--vary gives 65 settings; at most 64");
}

TEST(Grading, Base64MatchesRfc4648) {
    auto b = [](const std::string& s) { return base64(std::vector<std::uint8_t>(s.begin(), s.end())); };
    EXPECT_EQ(b(""), "");
    EXPECT_EQ(b("f"), "Zg==");
    EXPECT_EQ(b("fo"), "Zm8=");
    EXPECT_EQ(b("foo"), "Zm9v");
    EXPECT_EQ(b("foobar"), "Zm9vYmFy");
}

}  // namespace
}  // namespace glimmer
