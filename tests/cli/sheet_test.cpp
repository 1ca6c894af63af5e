// glimmer sheet: each cell of the grid is exactly what `glimmer render`
// draws for that value, under its label.
#include <algorithm>
#include <optional>

#include <gtest/gtest.h>

#include "image/image.h"
#include "run_glimmer.h"

using namespace glimmer_cli;

namespace {

// The top-left corner of the first place, from column `fromX` on, where
// `cell` lies on `sheet` pixel for pixel.
std::optional<std::pair<int, int>> findCell(const glimmer::Image& sheet, const glimmer::Image& cell, int fromX) {
    for (int y0 = 0; y0 + cell.height <= sheet.height; ++y0)
        for (int x0 = std::max(fromX, 0); x0 + cell.width <= sheet.width; ++x0) {
            bool same = true;
            for (int y = 0; y < cell.height && same; ++y)
                // Pointers, not &v[i]: the last row's end is one past the vector's
                // end, which the bounds-checked operator[] refuses.
                same = std::equal(cell.u8.data() + size_t(y) * size_t(cell.width) * 4,
                                  cell.u8.data() + size_t(y + 1) * size_t(cell.width) * 4,
                                  sheet.u8.data() + (size_t(y0 + y) * size_t(sheet.width) + size_t(x0)) * 4);
            if (same) return std::make_pair(x0, y0);
        }
    return std::nullopt;
}

TEST(CliSheet, CellsAreTheRendersForEachValue) {
    TempDir dir;
    auto r = runGlimmer({"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,2,4", "--set", "uHalfSize=3", "--size",
                         "32x32", "--backend", "osmesa", "-o", dir.file("sheet.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("sheet: 3/3 rendered"), std::string::npos) << r.err;
    glimmer::Image sheet;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("sheet.png"), sheet, why)) << why;
    const char* adds[] = {"0", "2", "4"};
    int lastX = -1, rowY = -1;
    for (int c = 0; c < 3; ++c) {
        std::string out = dir.file(std::string("cell") + adds[c] + ".png");
        auto rr = runGlimmer({"render", "scripts/bloom.glib", "--set", std::string("uAdd=") + adds[c], "--set",
                              "uHalfSize=3", "--size", "32x32", "--backend", "osmesa", "-o", out});
        ASSERT_EQ(rr.exitCode, 0) << rr.err;
        glimmer::Image cell;
        ASSERT_TRUE(glimmer::loadImage(out, cell, why)) << why;
        // The cell is somewhere on the sheet, pixel for pixel, right of the one before, in one row.
        auto at = findCell(sheet, cell, lastX + 1);
        ASSERT_TRUE(at) << "cell " << c << " is not on the sheet";
        if (rowY >= 0) {
            EXPECT_EQ(at->second, rowY);
        }
        if (c > 0) {
            EXPECT_GE(at->first, lastX + 32 + 1) << "cell " << c;
        }
        lastX = at->first;
        rowY = at->second;
    }
    // The labels are above the first row, not over the cells.
    EXPECT_GE(rowY, 20);
}

TEST(CliSheet, AValueOutsideTheRangeIsAUsageError) {
    TempDir dir;
    auto r = runGlimmer({"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,9", "--size", "16x16", "--backend", "osmesa",
                         "-o", dir.file("sheet.png")});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--vary uAdd=9 is outside the range <0 4>"), std::string::npos) << r.err;
}

}  // namespace
