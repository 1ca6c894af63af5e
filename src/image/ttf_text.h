// Text through a real TrueType font: DejaVu Sans (Debian's fonts-dejavu-core),
// rasterised with stb_truetype (libstb-dev), found at run time. Sheet labels,
// the Pareto chart and the viewer's burned-in values all draw with it; when no
// font file is found they fall back to the bitmap font of image/text.h.
#pragma once
#include <cstdint>
#include <string>

#include "image/image.h"

namespace glimmer {

struct TextColor {
    std::uint8_t r = 255, g = 255, b = 255;
};

// The font file in use: $GLIMMER_FONT when it names a readable file ("none"
// turns TrueType off), else DejaVu Sans where Debian puts it; empty when
// there is none (the bitmap font is used).
std::string labelFontPath();

// The width `text` takes at a pixel height of `px` (one line, UTF-8).
int labelWidth(const std::string& text, float px);
// The height of one line at `px`: ascent to descent, rounded up.
int labelLineHeight(float px);

// Draws one line of `text` with the top of its line box at y, blending the
// glyphs' coverage in `color` over the picture. RGBA8 images only.
void drawLabel(Image& img, int x, int y, const std::string& text, float px, TextColor color = {});

// The same over a darkened box with a margin of px/4 (readable on any
// picture), lines split at '\n'; the box's size in `w`, `h` when given.
void drawLabelBoxed(Image& img, int x, int y, const std::string& text, float px, int* w = nullptr, int* h = nullptr);
void measureLabelBoxed(const std::string& text, float px, int& w, int& h);

// drawLabelBoxed as a layer of its own: an RGBA8 image (straight alpha) the
// size of the box which, laid over any picture with layOver (or a GPU's
// SRC_ALPHA, ONE_MINUS_SRC_ALPHA blending), gives what drawLabelBoxed draws
// there, within two 8-bit steps (its colour and alpha are each rounded to
// 8 bits). The viewer shows its "Show values" overlay
// with it, so the window and a saved PNG carry the same text in the same place.
Image labelLayer(const std::string& text, float px);
// Lays `layer` over `img` with its top left at x, y: out = a C + (1 - a) P.
void layOver(Image& img, const Image& layer, int x, int y);

}  // namespace glimmer
