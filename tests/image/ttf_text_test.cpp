// Labels through DejaVu Sans and stb_truetype: the font is found, glyphs
// land inside the measured box only, and size and text change the measure.
#include <gtest/gtest.h>

#include "image/ttf_text.h"
#include "util/pcg32.h"

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

// The viewer's overlay is a layer laid over the picture (by layOver in a
// saved PNG, by the GPU's blending in the window): over any picture it must
// give what drawLabelBoxed draws there, within two 8-bit steps (the layer's
// colour and alpha are each rounded to 8 bits, then the blend is).
TEST(TtfText, ALabelLayerOverAnyPictureIsTheBoxedLabel) {
    const std::string text = "uAdd = 2.5\nuHalfSize = 11";
    const float px = 15;
    const Image layer = labelLayer(text, px);
    int w = 0, h = 0;
    measureLabelBoxed(text, px, w, h);
    ASSERT_EQ(layer.width, w);
    ASSERT_EQ(layer.height, h);
    Pcg32 rng(3);
    Image picture = Image::rgba8(w + 20, h + 20);
    for (size_t i = 0; i < picture.u8.size(); ++i) picture.u8[i] = i % 4 == 3 ? 255 : std::uint8_t(rng.next() & 255);
    Image drawn = picture, laid = picture;
    drawLabelBoxed(drawn, 5, 7, text, px);
    layOver(laid, layer, 5, 7);
    int worst = 0;
    long glyphPixels = 0;
    for (size_t i = 0; i < drawn.u8.size(); ++i) {
        if (i % 4 == 3) continue;
        worst = std::max(worst, std::abs(int(drawn.u8[i]) - int(laid.u8[i])));
        glyphPixels += drawn.u8[i] == 255 && picture.u8[i] != 255;
    }
    EXPECT_LE(worst, 2);
    EXPECT_GT(glyphPixels, 50);  // the text is there, not only the box
    // The box darkens to a third (alpha 2/3), the stems are opaque white.
    EXPECT_EQ(layer.u8[3], 170);
}

}  // namespace
