#include "image/ttf_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <vector>

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC  // other libraries (Dear ImGui) carry their own copy
#include <stb/stb_truetype.h>

#include "image/text.h"

namespace glimmer {
namespace {

struct Font {
    std::string path;
    std::vector<unsigned char> bytes;
    stbtt_fontinfo info{};
    bool ok = false;
};

const Font& font() {
    static const Font f = [] {
        Font out;
        std::vector<std::string> candidates;
        if (const char* e = std::getenv("GLIMMER_FONT"); e && *e) {
            if (std::string(e) == "none") return out;
            candidates.push_back(e);
        }
        candidates.push_back("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
        for (const auto& c : candidates) {
            std::ifstream in(c, std::ios::binary);
            if (!in) continue;
            out.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            int offset = stbtt_GetFontOffsetForIndex(out.bytes.data(), 0);
            if (offset >= 0 && stbtt_InitFont(&out.info, out.bytes.data(), offset)) {
                out.path = c;
                out.ok = true;
                return out;
            }
        }
        out.bytes.clear();
        return out;
    }();
    return f;
}

// UTF-8 to code points; a malformed byte is taken as Latin-1.
std::vector<int> codepoints(const std::string& s) {
    std::vector<int> out;
    for (size_t i = 0; i < s.size();) {
        unsigned char c = static_cast<unsigned char>(s[i]);
        int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
        bool good = n >= 0 && i + size_t(n) < s.size();
        int cp = good ? (n == 0 ? c : c & (0x3F >> n)) : 0;
        for (int k = 1; good && k <= n; ++k) {
            unsigned char d = static_cast<unsigned char>(s[i + size_t(k)]);
            good = (d & 0xC0) == 0x80;
            cp = (cp << 6) | (d & 0x3F);
        }
        if (!good) {
            out.push_back(c);
            ++i;
            continue;
        }
        out.push_back(cp);
        i += size_t(n) + 1;
    }
    return out;
}

// Bitmap font scale that comes closest to `px` (its capitals are 7 pixels
// in a 12-pixel line).
int bitmapScale(float px) { return std::max(1, int(std::lround(px / 12.f))); }

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string l; std::getline(ss, l);) out.push_back(l);
    if (out.empty()) out.push_back("");
    return out;
}

}  // namespace

std::string labelFontPath() { return font().path; }

int labelWidth(const std::string& text, float px) {
    const Font& f = font();
    if (!f.ok) {
        int w = 0, h = 0;
        measureText(text, bitmapScale(px), w, h);
        return w - 6 * bitmapScale(px);  // without the box's padding
    }
    float scale = stbtt_ScaleForPixelHeight(&f.info, px);
    std::vector<int> cps = codepoints(text);
    float x = 0;
    for (size_t i = 0; i < cps.size(); ++i) {
        int advance = 0, lsb = 0;
        stbtt_GetCodepointHMetrics(&f.info, cps[i], &advance, &lsb);
        x += float(advance) * scale;
        if (i + 1 < cps.size()) x += float(stbtt_GetCodepointKernAdvance(&f.info, cps[i], cps[i + 1])) * scale;
    }
    return int(std::ceil(x));
}

int labelLineHeight(float px) {
    const Font& f = font();
    if (!f.ok) return 12 * bitmapScale(px);
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&f.info, &ascent, &descent, &gap);
    float scale = stbtt_ScaleForPixelHeight(&f.info, px);
    return int(std::ceil(float(ascent - descent) * scale));
}

void drawLabel(Image& img, int x, int y, const std::string& text, float px, TextColor color) {
    if (img.type != Image::Type::U8 || text.empty()) return;
    const Font& f = font();
    if (!f.ok) {
        // The bitmap font draws over a box of its own; keep it tight.
        int s = bitmapScale(px);
        drawText(img, x - 3 * s, y - 3 * s, text, s);
        return;
    }
    float scale = stbtt_ScaleForPixelHeight(&f.info, px);
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&f.info, &ascent, &descent, &gap);
    int baseline = y + int(std::lround(float(ascent) * scale));
    std::vector<int> cps = codepoints(text);
    float pen = float(x);
    for (size_t i = 0; i < cps.size(); ++i) {
        int advance = 0, lsb = 0;
        stbtt_GetCodepointHMetrics(&f.info, cps[i], &advance, &lsb);
        float shift = pen - std::floor(pen);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetCodepointBitmapBoxSubpixel(&f.info, cps[i], scale, scale, shift, 0, &x0, &y0, &x1, &y1);
        int gw = x1 - x0, gh = y1 - y0;
        if (gw > 0 && gh > 0) {
            std::vector<unsigned char> cov(size_t(gw) * size_t(gh));
            stbtt_MakeCodepointBitmapSubpixel(&f.info, cov.data(), gw, gh, gw, scale, scale, shift, 0, cps[i]);
            int ox = int(std::floor(pen)) + x0, oy = baseline + y0;
            for (int gy = 0; gy < gh; ++gy) {
                int py = oy + gy;
                if (py < 0 || py >= img.height) continue;
                for (int gx = 0; gx < gw; ++gx) {
                    int pxl = ox + gx;
                    if (pxl < 0 || pxl >= img.width) continue;
                    unsigned a = cov[size_t(gy) * size_t(gw) + size_t(gx)];
                    if (!a) continue;
                    std::uint8_t* p = &img.u8[(size_t(py) * size_t(img.width) + size_t(pxl)) * 4];
                    p[0] = std::uint8_t((p[0] * (255 - a) + color.r * a + 127) / 255);
                    p[1] = std::uint8_t((p[1] * (255 - a) + color.g * a + 127) / 255);
                    p[2] = std::uint8_t((p[2] * (255 - a) + color.b * a + 127) / 255);
                    p[3] = 255;
                }
            }
        }
        pen += float(advance) * scale;
        if (i + 1 < cps.size()) pen += float(stbtt_GetCodepointKernAdvance(&f.info, cps[i], cps[i + 1])) * scale;
    }
}

void measureLabelBoxed(const std::string& text, float px, int& w, int& h) {
    int margin = std::max(2, int(px / 4));
    int widest = 0;
    auto ls = lines(text);
    for (const auto& l : ls) widest = std::max(widest, labelWidth(l, px));
    w = widest + 2 * margin;
    h = int(ls.size()) * labelLineHeight(px) + 2 * margin;
}

void drawLabelBoxed(Image& img, int x, int y, const std::string& text, float px, int* wOut, int* hOut) {
    if (img.type != Image::Type::U8) return;
    int w = 0, h = 0;
    measureLabelBoxed(text, px, w, h);
    if (wOut) *wOut = w;
    if (hOut) *hOut = h;
    for (int yy = std::max(y, 0); yy < std::min(y + h, img.height); ++yy)
        for (int xx = std::max(x, 0); xx < std::min(x + w, img.width); ++xx) {
            std::uint8_t* p = &img.u8[(size_t(yy) * size_t(img.width) + size_t(xx)) * 4];
            p[0] = std::uint8_t(p[0] / 3);
            p[1] = std::uint8_t(p[1] / 3);
            p[2] = std::uint8_t(p[2] / 3);
            p[3] = 255;
        }
    int margin = std::max(2, int(px / 4));
    int line = 0;
    for (const auto& l : lines(text)) drawLabel(img, x + margin, y + margin + line++ * labelLineHeight(px), l, px);
}

// The layer from two drawings of the box, over black and over white: over
// black a pixel is a C, over white a C + (1 - a) 255, so their difference
// gives a and then C (no second blending rule to keep in step with drawLabelBoxed).
Image labelLayer(const std::string& text, float px) {
    int w = 0, h = 0;
    measureLabelBoxed(text, px, w, h);
    if (w <= 0 || h <= 0) return {};
    Image black = Image::rgba8(w, h), white = Image::rgba8(w, h);
    for (size_t i = 0; i < white.u8.size(); ++i) white.u8[i] = 255, black.u8[i] = (i % 4 == 3) ? 255 : 0;
    drawLabelBoxed(black, 0, 0, text, px);
    drawLabelBoxed(white, 0, 0, text, px);
    Image layer = Image::rgba8(w, h);
    for (size_t p = 0; p < size_t(w) * size_t(h); ++p) {
        int spread = 0;
        for (size_t c = 0; c < 3; ++c) spread = std::max(spread, int(white.u8[p * 4 + c]) - int(black.u8[p * 4 + c]));
        const double a = 1.0 - spread / 255.0;
        layer.u8[p * 4 + 3] = std::uint8_t(std::lround(a * 255.0));
        for (size_t c = 0; c < 3; ++c)
            layer.u8[p * 4 + c] = a > 0 ? std::uint8_t(std::min(255.0, std::round(black.u8[p * 4 + c] / a))) : 0;
    }
    return layer;
}

void layOver(Image& img, const Image& layer, int x, int y) {
    if (img.type != Image::Type::U8 || layer.type != Image::Type::U8) return;
    for (int ly = 0; ly < layer.height; ++ly) {
        const int iy = y + ly;
        if (iy < 0 || iy >= img.height) continue;
        for (int lx = 0; lx < layer.width; ++lx) {
            const int ix = x + lx;
            if (ix < 0 || ix >= img.width) continue;
            const std::uint8_t* l = &layer.u8[(size_t(ly) * size_t(layer.width) + size_t(lx)) * 4];
            std::uint8_t* p = &img.u8[(size_t(iy) * size_t(img.width) + size_t(ix)) * 4];
            const double a = l[3] / 255.0;
            for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::lround(a * l[c] + (1.0 - a) * p[c]));
        }
    }
}

}  // namespace glimmer
