// Text drawn into pixels with stb_easy_font: the bitmap font that
// image/ttf_text.h falls back on when no TrueType file is found, and the
// labels of stand-in textures.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// Draws `text` (newlines start new lines) with its top-left corner at
// (x, y), row 0 at the top, each font pixel `scale` image pixels, over a
// dark box so it stays readable on any picture. RGBA8 images only.
void drawText(Image& img, int x, int y, const std::string& text, int scale = 2);

// Where drawText puts the dark box and the white quads of the glyphs, in
// image pixels (x0, y0, x1, y1; x1 and y1 excluded).
struct TextLayout {
    std::array<int, 4> box{};
    std::vector<std::array<int, 4>> quads;
};
TextLayout layoutText(int x, int y, const std::string& text, int scale = 2);

// The size drawText would cover, box included.
void measureText(const std::string& text, int scale, int& width, int& height);

}  // namespace glimmer
