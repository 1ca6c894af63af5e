// The overlay text burned into saved PNGs: white glyph pixels inside a
// darkened box, nothing outside it.
#include <gtest/gtest.h>

#include "image/text.h"

using namespace glimmer;

namespace {

TEST(Text, DrawsGlyphsInsideItsBoxOnly) {
    Image img = Image::rgba8(200, 60);
    for (size_t i = 0; i < img.u8.size(); ++i) img.u8[i] = 120;
    int w = 0, h = 0;
    measureText("uAdd = 2", 2, w, h);
    ASSERT_GT(w, 20);
    ASSERT_GT(h, 10);
    drawText(img, 10, 5, "uAdd = 2", 2);
    long white = 0, dark = 0, untouched = 0, outsideChanged = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
            bool inside = x >= 10 && x < 10 + w && y >= 5 && y < 5 + h;
            if (!inside) {
                outsideChanged += p[0] != 120;
                continue;
            }
            if (p[0] == 255) ++white;
            else if (p[0] == 40) ++dark;  // the picture darkened to a third
            else ++untouched;
        }
    }
    EXPECT_EQ(outsideChanged, 0);
    EXPECT_EQ(untouched, 0);
    EXPECT_GT(white, 50);
    EXPECT_GT(dark, white);
}

TEST(Text, MoreLinesMakeATallerBox) {
    int w1 = 0, h1 = 0, w2 = 0, h2 = 0;
    measureText("a", 1, w1, h1);
    measureText("a\nb", 1, w2, h2);
    EXPECT_GT(h2, h1);
}

TEST(Text, ClipsAtTheImageEdge) {
    Image img = Image::rgba8(8, 8);
    drawText(img, 4, 4, "a long line that runs off the picture", 3);  // must not write out of bounds
    EXPECT_EQ(img.width, 8);
}

}  // namespace
