// Sheet labels fit their cells: with two --vary at any cell size no text
// overlaps another or a cell, none is smaller than the legible minimum, and
// when "name = value" cannot fit, a legend below says what the short
// headers mean.
#include <gtest/gtest.h>

#include "sheet/sheet_layout.h"
#include "image/ttf_text.h"

namespace glimmer {
namespace {

struct Box {
    int x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

Box boxOf(const SheetText& t) {
    return {t.x, t.y, t.x + labelWidth(t.text, t.px), t.y + labelLineHeight(t.px)};
}

void expectReadable(const SheetLayout& L, int cols, int rows, const std::string& what) {
    std::vector<Box> cells;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            auto [x, y] = L.cellOrigin(c, r);
            cells.push_back({x, y, x + L.cellW, y + L.cellH});
            EXPECT_LE(x + L.cellW, L.width) << what;
            EXPECT_LE(y + L.cellH, L.height) << what;
        }
    for (size_t i = 0; i < L.texts.size(); ++i) {
        const SheetText& t = L.texts[i];
        Box b = boxOf(t);
        EXPECT_GE(t.px, kMinLabelPx) << what << ": " << t.text;
        EXPECT_GE(b.x0, 0) << what << ": " << t.text;
        EXPECT_LE(b.x1, L.width) << what << ": " << t.text;
        EXPECT_LE(b.y1, L.height) << what << ": " << t.text;
        for (const Box& c : cells) EXPECT_FALSE(b.overlaps(c)) << what << ": '" << t.text << "' covers a cell";
        for (size_t j = i + 1; j < L.texts.size(); ++j)
            EXPECT_FALSE(b.overlaps(boxOf(L.texts[j]))) << what << ": '" << t.text << "' and '" << L.texts[j].text
                                                        << "' overlap";
    }
}

TEST(SheetLayout, TwoVariesFitAtEverySize) {
    std::vector<std::string> adds{"0", "0.5", "2", "4"}, halves{"0", "3", "11"};
    for (int size : {16, 32, 48, 64, 128, 256}) {
        SheetLayout L = layoutSheet("bloom.glib   uHalfSize = 3   uAdd = 2", "uAdd", adds, "uHalfSize", halves, size,
                                    size);
        expectReadable(L, 4, 3, std::to_string(size) + " px");
    }
}

TEST(SheetLayout, FullHeadersWhenTheyFitElseALegend) {
    std::vector<std::string> adds{"0", "2", "4"}, halves{"0", "3", "11"};
    SheetLayout big = layoutSheet("bloom.glib", "uAdd", adds, "uHalfSize", halves, 128, 128);
    EXPECT_FALSE(big.legend);
    bool found = false;
    for (const auto& t : big.texts) found |= t.text == "uAdd = 2";
    EXPECT_TRUE(found);
    // "uBrightnessScale = 0.125" cannot fit 40 px at 9 px or more.
    SheetLayout small = layoutSheet("bloom.glib", "uBrightnessScale", {"0.125", "0.25"}, "uHalfSize", halves, 40, 40);
    EXPECT_TRUE(small.legend);
    expectReadable(small, 2, 3, "40 px, long name");
    std::string all;
    for (const auto& t : small.texts) all += t.text + "\n";
    EXPECT_NE(all.find("uBrightnessScale"), std::string::npos) << all;
    EXPECT_NE(all.find("0.125"), std::string::npos) << all;
}

TEST(SheetLayout, TheTitleCarriesTheSetValuesAndWraps) {
    SheetLayout L = layoutSheet("bloom.glib   uHalfSize = 3   uAdd = 2   uThreshold = 0.75", "uAdd", {"0", "1"}, "", {},
                                32, 32);
    std::string all;
    for (const auto& t : L.texts) all += t.text + "\n";
    EXPECT_NE(all.find("uHalfSize = 3"), std::string::npos) << all;
    EXPECT_NE(all.find("uThreshold = 0.75"), std::string::npos) << all;
    expectReadable(L, 2, 1, "title");
}

}  // namespace
}  // namespace glimmer
