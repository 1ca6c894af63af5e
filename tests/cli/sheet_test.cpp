// glimmer sheet: each cell of the grid is exactly what `glimmer render`
// draws for that value, under its label.
#include <gtest/gtest.h>

#include "image/image.h"
#include "run_glimmer.h"

using namespace glimmer_cli;

namespace {

TEST(CliSheet, CellsAreTheRendersForEachValue) {
    TempDir dir;
    auto r = runGlimmer({"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,2,4", "--set", "uHalfSize=3", "--size",
                         "32x32", "--backend", "osmesa", "-o", dir.file("sheet.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("sheet: 3/3 rendered"), std::string::npos) << r.err;
    glimmer::Image sheet;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("sheet.png"), sheet, why)) << why;
    // Three cells of 32 with 8 px gaps; one row with a 28 px label above.
    ASSERT_EQ(sheet.width, 3 * (32 + 8) + 8);
    ASSERT_EQ(sheet.height, 32 + 8 + 28 + 8);
    const char* adds[] = {"0", "2", "4"};
    for (int c = 0; c < 3; ++c) {
        std::string out = dir.file(std::string("cell") + adds[c] + ".png");
        auto rr = runGlimmer({"render", "scripts/bloom.glib", "--set", std::string("uAdd=") + adds[c], "--set",
                              "uHalfSize=3", "--size", "32x32", "--backend", "osmesa", "-o", out});
        ASSERT_EQ(rr.exitCode, 0) << rr.err;
        glimmer::Image cell;
        ASSERT_TRUE(glimmer::loadImage(out, cell, why)) << why;
        int x0 = 8 + c * 40, y0 = 8 + 28;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                for (int k = 0; k < 4; ++k)
                    ASSERT_EQ(sheet.u8[(size_t(y0 + y) * size_t(sheet.width) + size_t(x0 + x)) * 4 + size_t(k)],
                              cell.u8[(size_t(y) * 32 + size_t(x)) * 4 + size_t(k)])
                        << "cell " << c << " pixel " << x << "," << y;
    }
}

TEST(CliSheet, AValueOutsideTheRangeIsAUsageError) {
    TempDir dir;
    auto r = runGlimmer({"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,9", "--size", "16x16", "--backend", "osmesa",
                         "-o", dir.file("sheet.png")});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--set uAdd=9 is outside the range <0 4>"), std::string::npos) << r.err;
}

}  // namespace
