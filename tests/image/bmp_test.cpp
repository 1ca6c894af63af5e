#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/test_images.h"

using namespace glimmer;
using Bytes = std::vector<std::uint8_t>;

namespace {

void put16(Bytes& b, std::size_t at, std::uint32_t v) {
    b[at] = std::uint8_t(v), b[at + 1] = std::uint8_t(v >> 8);
}
void put32(Bytes& b, std::size_t at, std::uint32_t v) {
    put16(b, at, v), put16(b, at + 2, v >> 16);
}

// A BMP built by hand, independent of encodeBmp. `rows` are the file's rows in
// file order, already padded.
Bytes makeBmp(int w, int h, int bpp, std::uint32_t headerSize, std::uint32_t compression,
              const Bytes& pixels, const std::vector<std::uint32_t>& masks = {}) {
    const std::uint32_t extra = headerSize == 40 ? std::uint32_t(masks.size() * 4) : 0;
    const std::uint32_t offset = 14 + headerSize + extra;
    Bytes b(offset, 0);
    b[0] = 'B', b[1] = 'M';
    put32(b, 2, std::uint32_t(offset + pixels.size()));
    put32(b, 10, offset);
    put32(b, 14, headerSize);
    put32(b, 18, std::uint32_t(w));
    put32(b, 22, std::uint32_t(h));
    put16(b, 26, 1);
    put16(b, 28, std::uint32_t(bpp));
    put32(b, 30, compression);
    put32(b, 34, std::uint32_t(pixels.size()));
    for (std::size_t i = 0; i < masks.size(); ++i) put32(b, 54 + 4 * i, masks[i]);
    b.insert(b.end(), pixels.begin(), pixels.end());
    return b;
}

// Texel (x, y) of the 3x5 test picture, y counted from the top.
std::uint8_t chan(int x, int y, int c) { return std::uint8_t(10 * x + 50 * y + c); }

Bytes pixels24(int w, int h, bool topDown) {
    const int stride = (w * 3 + 3) & ~3;
    Bytes px(std::size_t(stride) * h, 0xEE);  // padding is junk on purpose
    for (int row = 0; row < h; ++row) {
        const int y = topDown ? row : h - 1 - row;
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) px[row * stride + x * 3 + c] = chan(x, y, 2 - c);  // BGR
    }
    return px;
}

void expectTexel(const Image& img, int x, int y, int r, int g, int b, int a) {
    const std::uint8_t* p = img.u8.data() + (std::size_t(y) * img.width + x) * 4;
    EXPECT_EQ(p[0], r) << "x=" << x << " y=" << y;
    EXPECT_EQ(p[1], g) << "x=" << x << " y=" << y;
    EXPECT_EQ(p[2], b) << "x=" << x << " y=" << y;
    EXPECT_EQ(p[3], a) << "x=" << x << " y=" << y;
}

std::string decodeError(const Bytes& b) {
    Image img;
    std::string error;
    EXPECT_FALSE(decodeBmp(b, img, error));
    return error;
}

}  // namespace

TEST(Bmp, Reads24BitBottomUpWithPaddedRows) {
    const Bytes file = makeBmp(3, 5, 24, 40, 0, pixels24(3, 5, false));
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    ASSERT_EQ(img.width, 3);
    ASSERT_EQ(img.height, 5);
    EXPECT_EQ(img.type, Image::Type::U8);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 3; ++x) expectTexel(img, x, y, chan(x, y, 0), chan(x, y, 1), chan(x, y, 2), 255);
    // Row 0 is the top: it is the LAST row stored in a bottom-up file.
    expectTexel(img, 0, 0, 0, 1, 2, 255);
    expectTexel(img, 2, 4, 220, 221, 222, 255);
}

TEST(Bmp, ReadsTopDown) {
    const Bytes file = makeBmp(3, -5, 24, 40, 0, pixels24(3, 5, true));
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    ASSERT_EQ(img.height, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 3; ++x) expectTexel(img, x, y, chan(x, y, 0), chan(x, y, 1), chan(x, y, 2), 255);
}

TEST(Bmp, Reads32BitV5BitfieldsWithAlpha) {
    // Unusual masks (RGBA from the low byte up) so a reader that assumes BGRA fails.
    const std::vector<std::uint32_t> masks = {0x000000FF, 0x0000FF00, 0x00FF0000, 0xFF000000};
    Bytes px;
    // 2x2, bottom-up: bottom row first.
    const std::uint8_t bottom[] = {1, 2, 3, 40, 5, 6, 7, 80};
    const std::uint8_t top[] = {9, 10, 11, 120, 13, 14, 15, 160};
    px.insert(px.end(), bottom, bottom + 8);
    px.insert(px.end(), top, top + 8);
    Bytes file = makeBmp(2, 2, 32, 124, 3, px, masks);
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    expectTexel(img, 0, 0, 9, 10, 11, 120);
    expectTexel(img, 1, 0, 13, 14, 15, 160);
    expectTexel(img, 0, 1, 1, 2, 3, 40);
    expectTexel(img, 1, 1, 5, 6, 7, 80);
}

TEST(Bmp, Reads32BitBitfieldsWithNarrowMasks) {
    // 5-6-5 in a 32-bit pixel: widening must scale to the full 0..255 range.
    const std::vector<std::uint32_t> masks = {0xF800, 0x07E0, 0x001F};
    Bytes px(4, 0);
    put32(px, 0, 0xF800 | (32u << 5) | 0);  // r max, g about half, b zero
    const Bytes file = makeBmp(1, 1, 32, 40, 3, px, masks);
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    expectTexel(img, 0, 0, 255, 130, 0, 255);
}

TEST(Bmp, AllZeroAlphaIsOpaque) {
    Bytes px = {1, 2, 3, 0, 4, 5, 6, 0};  // BGRX
    const Bytes file = makeBmp(2, 1, 32, 40, 0, px);
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    expectTexel(img, 0, 0, 3, 2, 1, 255);
    expectTexel(img, 1, 0, 6, 5, 4, 255);
}

TEST(Bmp, SomeZeroAlphaIsKept) {
    Bytes px = {1, 2, 3, 0, 4, 5, 6, 200};
    const Bytes file = makeBmp(2, 1, 32, 40, 0, px);
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    expectTexel(img, 0, 0, 3, 2, 1, 0);
    expectTexel(img, 1, 0, 6, 5, 4, 200);
}

TEST(Bmp, ReadsV4Header24Bit) {
    const Bytes file = makeBmp(3, 5, 24, 108, 0, pixels24(3, 5, false));
    Image img;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, img, error)) << error;
    expectTexel(img, 1, 3, chan(1, 3, 0), chan(1, 3, 1), chan(1, 3, 2), 255);
}

TEST(Bmp, Errors) {
    EXPECT_EQ(decodeError({'P', 'K', 3, 4}), "not a BMP file");
    EXPECT_EQ(decodeError({}), "not a BMP file");
    EXPECT_EQ(decodeError(makeBmp(4, 4, 8, 40, 0, Bytes(16, 0))),
              "unsupported BMP bit depth 8 (Glimmer reads 24- and 32-bit BMP)");
    EXPECT_EQ(decodeError(makeBmp(4, 4, 8, 40, 1, Bytes(16, 0))),
              "BMP is compressed (RLE); Glimmer reads uncompressed BMP");
    EXPECT_EQ(decodeError(makeBmp(4, 4, 4, 40, 2, Bytes(16, 0))),
              "BMP is compressed (RLE); Glimmer reads uncompressed BMP");

    Bytes full = makeBmp(3, 5, 24, 40, 0, pixels24(3, 5, false));
    full.resize(full.size() - 13);
    EXPECT_EQ(decodeError(full), "truncated BMP: pixel data needs 57 bytes at offset 54, file has 101");
    EXPECT_EQ(decodeError(Bytes(full.begin(), full.begin() + 30)),
              "truncated BMP: info header needs 54 bytes, file has 30");
    EXPECT_EQ(decodeError({'B', 'M', 0, 0, 0}), "truncated BMP: file header needs 18 bytes, file has 5");
}

TEST(Bmp, AcceptsMissingPaddingOnLastRow) {
    Bytes file = makeBmp(3, 5, 24, 40, 0, pixels24(3, 5, false));
    file.resize(file.size() - 3);
    Image img;
    std::string error;
    EXPECT_TRUE(decodeBmp(file, img, error)) << error;
}

TEST(Bmp, RejectsAbsurdSizes) {
    Bytes file = makeBmp(3, 5, 24, 40, 0, pixels24(3, 5, false));
    put32(file, 18, 0x7FFFFFFF);
    EXPECT_EQ(decodeError(file), "BMP has an unusable size 2147483647x5");
    put32(file, 18, 3);
    put32(file, 22, 0x80000000u);  // INT_MIN: negating it must not overflow
    EXPECT_EQ(decodeError(file), "BMP has an unusable size 3x-2147483648");
    put32(file, 22, 5);
    put32(file, 10, 20);
    EXPECT_EQ(decodeError(file), "BMP pixel data offset 20 points into its headers");
}

// Truncations and corrupted header bytes must give an error or a picture,
// never a crash or an out-of-bounds read (run under ASan to be thorough).
TEST(Bmp, FuzzTruncatedAndCorruptedNeverCrash) {
    const std::vector<std::uint32_t> masks = {0x00FF0000, 0x0000FF00, 0x000000FF, 0xFF000000};
    Bytes px(7 * 3 * 4);
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = std::uint8_t(i * 7);
    const Bytes sources[] = {makeBmp(3, 5, 24, 40, 0, pixels24(3, 5, false)),
                             makeBmp(7, -3, 32, 124, 3, px, masks), makeBmp(7, 3, 32, 40, 3, px, masks)};
    int decoded = 0, failed = 0;
    for (const Bytes& good : sources) {
        for (std::size_t n = 0; n < good.size(); ++n) {
            Image img;
            std::string error;
            // Copy into an exact-size buffer so reads past the end are real overreads.
            const Bytes prefix(good.begin(), good.begin() + std::ptrdiff_t(n));
            if (decodeBmp(prefix, img, error)) {
                ++decoded;
            } else {
                ++failed;
                EXPECT_FALSE(error.empty());
            }
        }
        std::uint32_t state = 12345;
        auto rnd = [&] { return state = state * 1664525u + 1013904223u; };
        const std::uint8_t specials[] = {0, 1, 0x7F, 0x80, 0xFF};
        for (int trial = 0; trial < 4000; ++trial) {
            Bytes bad = good;
            const int edits = 1 + int(rnd() % 4);
            for (int e = 0; e < edits; ++e) {
                const std::size_t at = rnd() % 70;  // the headers and masks
                bad[at] = (rnd() & 1) ? specials[rnd() % 5] : std::uint8_t(rnd() >> 24);
            }
            if (rnd() % 3 == 0) bad.resize(rnd() % bad.size());
            Image img;
            std::string error;
            if (decodeBmp(bad, img, error)) {
                ++decoded;
                ASSERT_EQ(img.u8.size(), std::size_t(img.width) * img.height * 4);
            } else {
                ++failed;
                EXPECT_FALSE(error.empty());
            }
        }
    }
    EXPECT_GT(decoded, 0);
    EXPECT_GT(failed, 0);
}

TEST(Bmp, EncodeDecodeRoundTrip) {
    const Image src = makeNoiseImage(13, 7, 99);  // odd width: padded rows
    const Bytes file = encodeBmp(src);
    ASSERT_EQ(file.size(), 54u + 40u * 7u);
    Image back;
    std::string error;
    ASSERT_TRUE(decodeBmp(file, back, error)) << error;
    ASSERT_EQ(back.width, 13);
    ASSERT_EQ(back.height, 7);
    EXPECT_EQ(back.u8, src.u8);  // noise alpha is 255, which 24-bit gives back
}

TEST(Bmp, EncodeWritesBottomUp) {
    Image img = Image::rgba8(1, 2);
    img.u8 = {10, 20, 30, 255, 40, 50, 60, 255};  // top, bottom
    const Bytes file = encodeBmp(img);
    ASSERT_EQ(file.size(), 54u + 8u);
    const Bytes expectedPixels = {60, 50, 40, 0, 30, 20, 10, 0};
    EXPECT_EQ(Bytes(file.begin() + 54, file.end()), expectedPixels);
}
