// glimmer tradeoff end to end, and every bloom lab script checked.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "image/image.h"
#include "run_glimmer.h"

using namespace glimmer_cli;

namespace {

TEST(CliTradeoff, WritesTableCsvJsonAndChart) {
    TempDir dir;
    auto r = runGlimmer({"tradeoff", "--size", "48x32", "--methods", "sep9", "--repeat", "1", "--backend", "osmesa",
                         "-o", dir.file("t")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("48x32 RGBA16F"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("tradeoff: 3/3 sep9 x4"), std::string::npos) << r.err;
    std::ifstream csv(dir.file("t.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.substr(0, 27), "method,family,taps,passes,m");
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        // Column 9 is the numerical PSNR: the GPU must match its own kernel's reference.
        std::stringstream ss(line);
        std::string cell;
        for (int i = 0; i < 9; ++i) std::getline(ss, cell, ',');
        EXPECT_GT(std::stod(cell), 50.0) << line;
    }
    EXPECT_EQ(rows, 3);
    std::ifstream json(dir.file("t.json"));
    std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"method\": \"sep9 x2\""), std::string::npos);
    EXPECT_NE(text.find("\"health\": {\"nan\": 0, \"inf\": 0, \"negative\": 0, \"above_65504\": 0}"), std::string::npos)
        << text;
    glimmer::Image chart;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("t.png"), chart, why)) << why;
    EXPECT_EQ(chart.width, 800);
}

TEST(CliTradeoff, UnknownFormatIsAUsageError) {
    auto r = runGlimmer({"tradeoff", "--format", "RGB9", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--format 'RGB9' is not RGBA8, RGBA16F, RGBA32F or R11F_G11F_B10F"), std::string::npos) << r.err;
}

class BloomScripts : public ::testing::TestWithParam<std::string> {};

TEST_P(BloomScripts, CheckWithoutErrors) {
    auto r = runGlimmer({"check", "scripts/bloom/" + GetParam() + ".glib", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("error:"), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Lab, BloomScripts,
                         ::testing::Values("bailey", "learnopengl", "overflow", "willems", "soltrader", "cod", "kawase"));

}  // namespace

namespace {

// A script as the input: its picture is what gets blurred.
TEST(CliTradeoffScript, BlursTheScriptsPicture) {
    glimmer_cli::TempDir dir;
    auto r = glimmer_cli::runGlimmer({"tradeoff", "scripts/shapes.glib", "--size", "40x40", "--methods", "kawase x2",
                                      "--repeat", "1", "--backend", "osmesa", "-o", dir.file("s")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("40x40 RGBA16F"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("kawase x2"), std::string::npos) << r.out;
}

}  // namespace
