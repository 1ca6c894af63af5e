// glimmer batch: every script gets its PNG or a failed line in the report,
// a runaway script costs its own time limit and nothing else, and shards
// partition the list exactly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_glimmer.h"

namespace {

namespace fs = std::filesystem;
using glimmer_cli::countOf;
using glimmer_cli::readAll;
using glimmer_cli::writeSolid;
using glimmer_cli::runGlimmer;
using glimmer_cli::TempDir;
using glimmer_cli::writeRunawayScript;

// One line of --report, read with a JSON library (an empty object when it
// is not a JSON object: the checks on it then fail, saying the line).
nlohmann::json reportLine(const std::string& line) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    return j.is_object() ? j : nlohmann::json::object();
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

TEST(CliBatch, EachScriptIsRenderedOrReportedAndARunawayCostsOnlyItself) {
    TempDir dir;
    std::string good = writeSolid(dir, "good.glib", 0);
    std::ofstream(dir.file("broken.glib")) << "Ortho -1 1 -1\n";
    std::string slow = writeRunawayScript(dir);
    std::string other = writeSolid(dir, "other.glib", 1);
    auto r = runGlimmer({"batch", good, dir.file("broken.glib"), slow, other, "-o", dir.file("out"),
                         "--report", dir.file("r.jsonl"), "--size", "64x64", "--backend", "osmesa", "--timeout", "2",
                         "--jobs", "2"}, 60);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 1) << r.err;  // some scripts failed
    auto report = lines(readAll(dir.file("r.jsonl")));
    ASSERT_EQ(report.size(), 4u);  // one line per script, in the order given
    EXPECT_EQ(reportLine(report[0]).value("exit", -1), 0) << report[0];
    EXPECT_EQ(reportLine(report[0]).value("script", ""), good) << report[0];
    EXPECT_EQ(reportLine(report[1]).value("exit", -1), 1) << report[1];
    EXPECT_NE(reportLine(report[1]).value("diagnostics", "").find("Ortho takes 4 numbers, got 3"), std::string::npos)
        << report[1];
    EXPECT_TRUE(reportLine(report[1]).at("output").is_null()) << report[1];
    EXPECT_EQ(reportLine(report[2]).value("exit", -1), 1) << report[2];
    EXPECT_NE(reportLine(report[2]).value("diagnostics", "").find("stopped after 2 s (--timeout 2)"), std::string::npos)
        << report[2];
    EXPECT_EQ(reportLine(report[3]).value("exit", -1), 0) << report[3];
    EXPECT_TRUE(reportLine(report[3]).at("ms").at("render").is_number()) << report[3];
    EXPECT_EQ(countOf(r.err, "wrote 2 of 4 scripts to "), 1) << r.err;
    // What batch wrote is what `glimmer render` writes for the same script.
    std::vector<std::string> pngs;
    for (const auto& e : fs::directory_iterator(dir.file("out"))) pngs.push_back(e.path().string());
    ASSERT_EQ(pngs.size(), 2u);
    auto ref = runGlimmer({"-q", "render", good, "-o", dir.file("good.png"), "--size", "64x64", "--backend", "osmesa"});
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    int same = 0;
    for (const auto& p : pngs) same += readAll(p) == readAll(dir.file("good.png"));
    EXPECT_EQ(same, 1);
}

// --strict in a batch as in render: a float target the screen reads that
// holds a NaN fails the script, says why in its report line, and writes no
// picture.
TEST(CliBatch, StrictFailsAScriptWhoseTargetHoldsANan) {
    TempDir dir;
    for (const char* f : {"st.vert", "nan.frag"}) fs::copy_file(fs::path(GLIMMER_TEST_DATA) / "cli" / f, dir.path() / f);
    std::ofstream(dir.file("show.frag")) << "#version 330 compatibility\nuniform sampler2D uT;\nin vec2 vST;\n"
                                            "void main() { gl_FragColor = vec4(texture(uT, vST).rgb * 0.5, 1.); }\n";
    std::ofstream(dir.file("read.glib")) << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nTexture2D 6 16 16 RGBA16F\n"
                                            "RenderToTexture 6\nVertex st.vert\nFragment nan.frag\n"
                                            "Program Nan uZero <0. 0. 1.>\nQuadXY 0 1\nRenderToTexture\n"
                                            "Fragment show.frag\nProgram Show uT 6\nQuadXY 0 1\n";
    auto r = runGlimmer({"batch", dir.file("read.glib"), "-o", dir.file("out"), "--report", dir.file("r.jsonl"),
                         "--size", "32x32", "--backend", "osmesa", "--strict"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    auto report = lines(readAll(dir.file("r.jsonl")));
    ASSERT_EQ(report.size(), 1u);
    EXPECT_EQ(reportLine(report[0]).value("health", ""), "bad") << report[0];
    // The bad target named as render --health names it: nan.frag's 0/0
    // where s and t are past 0.9, texel centres 14.5/16 and 15.5/16 each
    // way, so 2x2 texels of three NaN channels, the first at column 14 of
    // the top row.
    EXPECT_EQ(reportLine(report[0]).value("diagnostics", ""),
              "health: unit 6 (RGBA16F 16x16): 12 NaN, 0 Inf, 0 negative, 0 above 65504; first bad pixel at 14,0\n"
              "glimmer: error: --strict: a target holds NaN, Inf, negative or out-of-range values\n") << report[0];
    EXPECT_TRUE(reportLine(report[0]).at("output").is_null()) << report[0];
}

// Issue 25: a report line is JSON whatever bytes a path or a diagnostic
// holds. A script named in Latin-1 (not UTF-8) was written into the line
// byte for byte, which no JSON reader takes; now each bad byte is U+FFFD.
TEST(CliBatch, AReportLineIsJsonWhenANameIsNotUtf8) {
    TempDir dir;
    const std::string latin1 = dir.file("J\xFCrgen.glib");  // Jürgen in Latin-1
    std::ofstream(latin1) << "Ortho -1 1 -1\n";
    auto r = runGlimmer({"batch", latin1, "-o", dir.file("out"), "--report", dir.file("r.jsonl"), "--size", "16x16",
                         "--backend", "osmesa"}, 60);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    auto report = lines(readAll(dir.file("r.jsonl")));
    ASSERT_EQ(report.size(), 1u);
    const nlohmann::json line = reportLine(report[0]);
    ASSERT_TRUE(line.is_object()) << report[0];
    EXPECT_EQ(line.value("script", ""), dir.file("J\xEF\xBF\xBDrgen.glib")) << report[0];
    EXPECT_NE(line.value("diagnostics", "").find("Ortho takes 4 numbers, got 3"), std::string::npos) << report[0];
}

TEST(CliBatch, ShardsPartitionTheListExactly) {
    TempDir dir;
    std::ofstream list(dir.file("class.txt"));
    list << "# a class of seven\n";
    for (int k = 0; k < 7; ++k) list << writeSolid(dir, "s" + std::to_string(k) + ".glib", k) << "\n";
    list.close();
    std::multiset<std::string> all;
    for (int shard = 1; shard <= 3; ++shard) {
        std::string out = dir.file("shard" + std::to_string(shard));
        auto r = runGlimmer({"-q", "batch", "--list", dir.file("class.txt"), "--shard", std::to_string(shard) + "/3",
                             "-o", out, "--size", "16x16", "--backend", "osmesa"}, 60);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        for (const auto& e : fs::directory_iterator(out)) all.insert(e.path().filename().string());
    }
    std::set<std::string> distinct(all.begin(), all.end());
    EXPECT_EQ(all.size(), 7u);       // every script once...
    EXPECT_EQ(distinct.size(), 7u);  // ...and none twice
    auto bad = runGlimmer({"batch", "--list", dir.file("class.txt"), "--shard", "4/3", "-o", dir.file("x")});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(bad.err, "glimmer: error: --shard '4/3' is not I/N with 1 <= I <= N\n");
}

}  // namespace
