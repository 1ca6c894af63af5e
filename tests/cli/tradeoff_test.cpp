// glimmer tradeoff end to end, and every bloom lab script checked.
#include <fstream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    ASSERT_TRUE(doc.is_object()) << dir.file("t.json") << " is not JSON";
    bool sep9x2 = false;
    for (const auto& m : doc["methods"]) {
        sep9x2 |= m["method"] == "sep9 x2";
        EXPECT_EQ(m["health"], nlohmann::json::parse(R"({"nan": 0, "inf": 0, "negative": 0, "above_65504": 0})"))
            << m.dump();
    }
    EXPECT_TRUE(sep9x2) << doc.dump(2);
    glimmer::Image chart;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("t.png"), chart, why)) << why;
    EXPECT_EQ(chart.width, 800);
}

// Every run is kept: the CSV's new columns (after the old ones, which keep
// their places) hold the fastest and slowest run around the median, the JSON
// the same and the verdict, and the header says which comparison it is.
TEST(CliTradeoff, KeepsTheSpreadOfTheRuns) {
    TempDir dir;
    auto r = runGlimmer({"tradeoff", "--size", "32x32", "--methods", "linear5 x1", "kawase x2", "--repeat", "3",
                         "--backend", "osmesa", "-o", dir.file("t")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("median of 3, natural width"), std::string::npos) << r.out;
    // Either a named winner beyond the noise or a tie: never a bare name.
    const bool winner = r.out.find("its slowest run beats every other candidate's fastest") != std::string::npos;
    const bool tie = r.out.find("tie within noise: ") != std::string::npos;
    const bool none = r.out.find("no method came within 40 dB") != std::string::npos;
    EXPECT_EQ(int(winner) + int(tie) + int(none), 1) << r.out;
    std::ifstream csv(dir.file("t.csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_NE(header.find(",above_65504,ms_min,ms_max,runs,target_sigma,floor_ms"), std::string::npos) << header;
    EXPECT_NE(r.out.find("texel-rate floor: "), std::string::npos) << r.out;
    // osmesa is llvmpipe, a CPU renderer: timed by glFinish and a wall clock (no GPU timer queries), and the
    // floor's line says why a method of few taps a pass can run under it there.
    EXPECT_NE(r.out.find("; on a CPU renderer shading, not fetching, sets the pace"), std::string::npos) << r.out;
    int rows = 0;
    std::vector<double> floorPerTap;
    while (std::getline(csv, line)) {
        ++rows;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
        ASSERT_EQ(cells.size(), 24u) << line;
        const double ms = std::stod(cells[4]), lo = std::stod(cells[19]), hi = std::stod(cells[20]);
        EXPECT_LE(lo, ms) << line;
        EXPECT_LE(ms, hi) << line;
        EXPECT_GT(lo, 0.0) << line;
        EXPECT_EQ(cells[21], "3") << line;
        EXPECT_EQ(cells[22], "") << line;  // target_sigma is empty at natural width
        // The floor: one measured time per tap, times the method's taps.
        const double floor = std::stod(cells[23]);
        EXPECT_GT(floor, 0.0) << line;
        floorPerTap.push_back(floor / std::stod(cells[2]));
    }
    EXPECT_EQ(rows, 2);
    ASSERT_EQ(floorPerTap.size(), 2u);
    EXPECT_NEAR(floorPerTap[0], floorPerTap[1], 1e-3 * floorPerTap[0]);
    std::ifstream json(dir.file("t.json"));
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    ASSERT_TRUE(doc.is_object()) << dir.file("t.json") << " is not JSON";
    EXPECT_EQ(doc["comparison"], "natural width") << doc.dump(2);
    EXPECT_TRUE(doc["fastest_within_40db"]["clear_winner"].is_boolean()) << doc.dump(2);
    ASSERT_EQ(doc["methods"].size(), 2u) << doc.dump(2);
    for (const auto& m : doc["methods"]) EXPECT_EQ(m["runs"], 3) << m.dump();
}

// --match-sigma: one method per family, each near the target, and the
// header, CSV and JSON say it is a matched comparison.
TEST(CliTradeoff, MatchSigmaScalesEachFamily) {
    TempDir dir;
    auto r = runGlimmer({"tradeoff", "--size", "32x32", "--match-sigma", "3", "--repeat", "1", "--backend", "osmesa",
                         "-o", dir.file("m")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("matched sigma = 3 (achieved "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("note: 1 run per method cannot show the noise"), std::string::npos) << r.out;
    std::ifstream csv(dir.file("m.csv"));
    std::string line;
    std::getline(csv, line);
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
        ASSERT_EQ(cells.size(), 24u) << line;
        EXPECT_EQ(cells[22], "3") << line;
        EXPECT_GT(std::stod(cells[23]), 0.0) << line;  // floor_ms
        EXPECT_NEAR(std::stod(cells[6]), 3.0, 0.6) << line;  // the achieved sigma
    }
    EXPECT_EQ(rows, 4);  // superblur, sep9, linear5, dual Kawase
    std::ifstream json(dir.file("m.json"));
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    ASSERT_TRUE(doc.is_object()) << dir.file("m.json") << " is not JSON";
    EXPECT_EQ(doc["comparison"], nlohmann::json::parse(R"({"matched_sigma": 3})")) << doc.dump(2);
}

TEST(CliTradeoff, MatchSigmaOutOfRangeIsAUsageError) {
    auto r = runGlimmer({"tradeoff", "--match-sigma", "40", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--match-sigma 40 is not between 0.5 and 16"), std::string::npos) << r.err;
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
