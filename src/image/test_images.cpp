#include "image/test_images.h"

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

// PCG32 (O'Neill): tiny, and the same numbers on every platform, unlike std::rand.
struct Pcg32 {
    std::uint64_t state, inc;
    explicit Pcg32(std::uint64_t seed, std::uint64_t seq = 54) : state(0), inc((seq << 1) | 1) {
        next();
        state += seed;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state;
        state = old * 6364136223846793005ull + inc;
        const std::uint32_t xorshifted = std::uint32_t(((old >> 18) ^ old) >> 27);
        const std::uint32_t rot = std::uint32_t(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
};

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
    Pcg32 rng(seed);
    for (std::size_t i = 0; i < img.u8.size(); i += 4) {
        const std::uint32_t r = rng.next();
        img.u8[i] = std::uint8_t(r);
        img.u8[i + 1] = std::uint8_t(r >> 8);
        img.u8[i + 2] = std::uint8_t(r >> 16);
        img.u8[i + 3] = 255;
    }
    return img;
}

}  // namespace glimmer
