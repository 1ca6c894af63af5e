#include "image/text.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <stb/stb_easy_font.h>

namespace glimmer {
namespace {

constexpr int kPad = 3;  // font pixels of box around the text

void fillRect(Image& img, int x0, int y0, int x1, int y1, std::uint8_t r, std::uint8_t g, std::uint8_t b, bool blend) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, img.width);
    y1 = std::min(y1, img.height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            std::uint8_t* p = &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
            if (blend) {  // darken to a third, so the picture still shows through
                p[0] = std::uint8_t(p[0] / 3);
                p[1] = std::uint8_t(p[1] / 3);
                p[2] = std::uint8_t(p[2] / 3);
            } else {
                p[0] = r;
                p[1] = g;
                p[2] = b;
            }
            p[3] = 255;
        }
    }
}

}  // namespace

void measureText(const std::string& text, int scale, int& width, int& height) {
    std::string copy = text;
    width = (stb_easy_font_width(copy.data()) + 2 * kPad) * scale;
    height = (stb_easy_font_height(copy.data()) + 2 * kPad) * scale;
}

TextLayout layoutText(int x, int y, const std::string& text, int scale) {
    TextLayout out;
    if (text.empty()) return out;
    int w = 0, h = 0;
    measureText(text, scale, w, h);
    out.box = {x, y, x + w, y + h};
    // Each character is a set of axis-aligned quads, 4 vertices of 16 bytes.
    std::vector<char> buffer(text.size() * 270 + 1024);
    std::string copy = text;
    int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
        const float* quad = v + q * 16;  // x, y, z, colour as 4 floats a vertex
        float qx0 = quad[0], qy0 = quad[1], qx1 = quad[8], qy1 = quad[9];
        out.quads.push_back({x + int(std::lround((qx0 + kPad) * scale)), y + int(std::lround((qy0 + kPad) * scale)),
                             x + int(std::lround((qx1 + kPad) * scale)), y + int(std::lround((qy1 + kPad) * scale))});
    }
    return out;
}

void drawText(Image& img, int x, int y, const std::string& text, int scale) {
    if (img.type != Image::Type::U8 || text.empty()) return;
    TextLayout l = layoutText(x, y, text, scale);
    fillRect(img, l.box[0], l.box[1], l.box[2], l.box[3], 0, 0, 0, true);
    for (const auto& q : l.quads) fillRect(img, q[0], q[1], q[2], q[3], 255, 255, 255, false);
}

}  // namespace glimmer
