#include "image/test_images.h"
#include "util/pcg32.h"

#include <algorithm>
#include <cstdint>

namespace glimmer {
namespace {

// Two pixels wide, at each eighth of the side, interior only: lines on the
// border would blur into the clamp-to-edge and muddy the picture.
bool onGridLine(int p, int size) {
    for (int k = 1; k < 8; ++k) {
        const int at = k * size / 8;
        if (p == at || p == at - 1) return true;
    }
    return false;
}

void fillRect(Image& img, int cx, int cy, int half, const std::uint8_t (&rgb)[3]) {
    for (int y = std::max(cy - half, 0); y < std::min(cy + half, img.height); ++y)
        for (int x = std::max(cx - half, 0); x < std::min(cx + half, img.width); ++x) {
            std::uint8_t* p = img.u8.data() + (std::size_t(y) * img.width + x) * 4;
            p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2], p[3] = 255;
        }
}

}  // namespace

Image makeGridImage(int width, int height) {
    Image img = Image::rgba8(width, height);
    const std::uint8_t background[3] = {12, 14, 20};  // ~0.05, 0.055, 0.08: dark, a little blue
    for (int y = 0; y < height; ++y) {
        const bool rowLine = onGridLine(y, height);
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = img.u8.data() + (std::size_t(y) * width + x) * 4;
            const bool line = rowLine || onGridLine(x, width);
            for (int c = 0; c < 3; ++c) p[c] = line ? 255 : background[c];
            p[3] = 255;
        }
    }
    // Squares centred in grid cells, well clear of the lines, so each glows
    // on its own.
    const int half = std::max(1, std::min(width, height) / 40);
    auto cellCentre = [](int cell, int size) { return (2 * cell + 1) * size / 16; };
    struct Square { int cx, cy; std::uint8_t rgb[3]; };
    const Square squares[] = {
        {1, 1, {255, 0, 0}}, {5, 2, {0, 255, 0}}, {2, 5, {0, 0, 255}}, {6, 6, {255, 255, 0}}};
    for (const Square& s : squares)
        fillRect(img, cellCentre(s.cx, width), cellCentre(s.cy, height), half, s.rgb);
    return img;
}

Image makeNoiseImage(int width, int height, unsigned seed) {
    Image img = Image::rgba8(width, height);
    Pcg32 rng(seed, 54);  // the stream the committed test pictures were made with
    for (std::size_t i = 0; i < img.u8.size(); i += 4) {
        const std::uint32_t r = rng.next();
        img.u8[i] = std::uint8_t(r);
        img.u8[i + 1] = std::uint8_t(r >> 8);
        img.u8[i + 2] = std::uint8_t(r >> 16);
        img.u8[i + 3] = 255;
    }
    return img;
}

Image makeHdrScene(int width, int height) {
    Image img = Image::rgbaF32(width, height);
    auto put = [&](int x, int y, float r, float g, float b) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        float* p = &img.f32[(size_t(y) * size_t(width) + size_t(x)) * 4];
        p[0] = r;
        p[1] = g;
        p[2] = b;
    };
    // The ground: a dim vertical gradient with faint tiles, never black, so
    // a blur's error shows everywhere, not only near the lights.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float g = 0.02f + 0.04f * float(y) / float(std::max(1, height - 1));
            float tile = ((x / 32 + y / 32) % 2) ? 0.005f : 0.f;
            put(x, y, g + tile, g + tile, g * 1.2f + tile);
            img.f32[(size_t(y) * size_t(width) + size_t(x)) * 4 + 3] = 1.f;
        }
    // Emitters: discs of rising brightness along the top, in four colours.
    const float levels[] = {1.5f, 2.f, 3.f, 5.f, 8.f, 15.f};
    const float tints[][3] = {{1, .9f, .7f}, {1, .4f, .2f}, {.3f, .6f, 1}, {.5f, 1, .4f}, {1, 1, 1}, {1, .8f, .9f}};
    for (int i = 0; i < 6; ++i) {
        int cx = int((i + 0.5) * width / 6.0), cy = height / 4;
        int r = std::max(1, width / 40);
        for (int y = -r; y <= r; ++y)
            for (int x = -r; x <= r; ++x)
                if (x * x + y * y <= r * r)
                    put(cx + x, cy + y, levels[i] * tints[i][0], levels[i] * tints[i][1], levels[i] * tints[i][2]);
    }
    // Bars: a thin bright line and a wide dim one, for a blur's shape along one axis.
    for (int x = width / 8; x < width * 7 / 8; ++x) {
        put(x, height / 2, 10.f, 10.f, 10.f);
        for (int t = 0; t < std::max(1, height / 32); ++t) put(x, height * 3 / 4 + t, 1.5f, 1.2f, 1.f);
    }
    // The firefly: one texel far brighter than anything else.
    put(width * 3 / 4, height * 5 / 8, 1000.f, 1000.f, 1000.f);
    return img;
}

}  // namespace glimmer
