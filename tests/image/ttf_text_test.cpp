// Labels through DejaVu Sans and stb_truetype: the font is found, glyphs
// land inside the measured box only, and size and text change the measure.
#include <gtest/gtest.h>

#include "image/ttf_text.h"

using namespace glimmer;

namespace {

TEST(TtfText, FindsDejaVu) {
    // fonts-dejavu-core is a build dependency (tools/install-deps.sh).
    EXPECT_EQ(labelFontPath(), "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
}

TEST(TtfText, MeasuresGrowWithSizeAndText) {
    EXPECT_GT(labelWidth("uAdd = 2", 18), labelWidth("uAdd = 2", 9));
    EXPECT_GT(labelWidth("uAdd = 22", 12), labelWidth("uAdd = 2", 12));
    EXPECT_EQ(labelWidth("", 12), 0);
    EXPECT_GE(labelLineHeight(12), 12);
    EXPECT_LE(labelLineHeight(12), 16);
    // Proportional, not fixed: an 'i' is narrower than an 'M'.
    EXPECT_LT(labelWidth("iiii", 14), labelWidth("MMMM", 14));
}

TEST(TtfText, GlyphsStayInsideTheirBox) {
    Image img = Image::rgba8(120, 40);
    for (size_t i = 0; i < img.u8.size(); ++i) img.u8[i] = i % 4 == 3 ? 255 : 0;
    const int x = 10, y = 8;
    const float px = 14;
    drawLabel(img, x, y, "σ = 2.5 ± 0.1", px);
    const int w = labelWidth("σ = 2.5 ± 0.1", px), h = labelLineHeight(px);
    long inside = 0, outside = 0, full = 0;
    for (int yy = 0; yy < img.height; ++yy)
        for (int xx = 0; xx < img.width; ++xx) {
            std::uint8_t v = img.u8[(size_t(yy) * size_t(img.width) + size_t(xx)) * 4];
            bool in = xx >= x - 1 && xx <= x + w && yy >= y && yy < y + h;
            if (v) (in ? inside : outside)++;
            full += v == 255;
        }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(inside, 60);
    EXPECT_GT(full, 10);             // solid stems
    EXPECT_GT(inside - full, 10);    // and anti-aliased edges: a real outline font
}

}  // namespace
