// BMP reader. Every offset and size comes from the file, so each is checked
// against the buffer before use; arithmetic is done in 64 bits.
#include "image/image.h"

#include <bit>
#include <cstdint>
#include <string>

namespace glimmer {
namespace {

constexpr std::uint32_t BI_RGB = 0, BI_RLE8 = 1, BI_RLE4 = 2, BI_BITFIELDS = 3,
                        BI_JPEG = 4, BI_PNG = 5, BI_ALPHABITFIELDS = 6;
// Far beyond any texture a GPU takes, and small enough that w*h*4 cannot overflow.
constexpr std::int64_t kMaxSide = 1 << 16;

std::uint32_t rd16(const std::uint8_t* p) { return p[0] | (p[1] << 8); }
std::uint32_t rd32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) |
           (std::uint32_t(p[3]) << 24);
}

// Pulls one channel out of a pixel through its mask and widens it to 8 bits.
struct Channel {
    std::uint32_t mask = 0;
    int shift = 0;
    int bits = 0;
    explicit Channel(std::uint32_t m = 0) : mask(m) {
        if (m) {
            shift = std::countr_zero(m);
            bits = std::popcount(m);
        }
    }
    std::uint8_t get(std::uint32_t px) const {
        if (!mask) return 0;
        const std::uint32_t v = (px & mask) >> shift;
        if (bits >= 8) return std::uint8_t(v >> (bits - 8));
        const std::uint32_t maxv = (1u << bits) - 1;
        return std::uint8_t((v * 255 + maxv / 2) / maxv);
    }
};

bool fail(std::string& error, std::string msg) {
    error = std::move(msg);
    return false;
}

}  // namespace

bool decodeBmp(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error) {
    const std::uint64_t size = bytes.size();
    const std::uint8_t* b = bytes.data();
    if (size < 2 || b[0] != 'B' || b[1] != 'M') return fail(error, "not a BMP file");
    if (size < 18) return fail(error, "truncated BMP: file header needs 18 bytes, file has " + std::to_string(size));

    const std::uint32_t pixelOffset = rd32(b + 10);
    const std::uint32_t headerSize = rd32(b + 14);
    if (headerSize == 12)
        return fail(error, "unsupported BMP header (OS/2 BITMAPCOREHEADER); Glimmer reads BITMAPINFOHEADER and later");
    if (headerSize < 40 || headerSize > 1024)
        return fail(error, "unsupported BMP header size " + std::to_string(headerSize));
    if (size < 14ull + headerSize)
        return fail(error, "truncated BMP: info header needs " + std::to_string(14ull + headerSize) +
                               " bytes, file has " + std::to_string(size));

    const std::int64_t width = std::int32_t(rd32(b + 18));
    const std::int64_t rawHeight = std::int32_t(rd32(b + 22));
    const std::uint32_t bpp = rd16(b + 28);
    const std::uint32_t compression = rd32(b + 30);

    if (compression == BI_RLE8 || compression == BI_RLE4)
        return fail(error, "BMP is compressed (RLE); Glimmer reads uncompressed BMP");
    if (compression == BI_JPEG || compression == BI_PNG)
        return fail(error, "BMP holds an embedded JPEG/PNG; Glimmer reads uncompressed BMP");
    if (bpp != 24 && bpp != 32)
        return fail(error, "unsupported BMP bit depth " + std::to_string(bpp) + " (Glimmer reads 24- and 32-bit BMP)");
    if (compression != BI_RGB && compression != BI_BITFIELDS && compression != BI_ALPHABITFIELDS)
        return fail(error, "unsupported BMP compression " + std::to_string(compression));
    if (compression != BI_RGB && bpp != 32)
        return fail(error, "BMP with bit fields must be 32-bit, this one is " + std::to_string(bpp) + "-bit");

    const bool topDown = rawHeight < 0;
    const std::int64_t height = topDown ? -rawHeight : rawHeight;
    if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
        return fail(error, "BMP has an unusable size " + std::to_string(width) + "x" + std::to_string(rawHeight));

    // BI_RGB 32-bit is BGRX; most writers put alpha in the X byte, so read it
    // and fall back to opaque below when it is all zero.
    Channel red(0x00FF0000), green(0x0000FF00), blue(0x000000FF), alpha(0xFF000000);
    std::uint64_t headersEnd = 14ull + headerSize;
    if (compression != BI_RGB) {
        // Masks sit in v2+ headers, or follow a 40-byte header directly.
        const std::uint32_t maskCount = compression == BI_ALPHABITFIELDS ? 4 : 3;
        if (headerSize == 40) headersEnd += 4ull * maskCount;
        if (size < 54ull + 4ull * maskCount)
            return fail(error, "truncated BMP: colour masks");
        red = Channel(rd32(b + 54));
        green = Channel(rd32(b + 58));
        blue = Channel(rd32(b + 62));
        const bool hasAlphaMask = maskCount == 4 || headerSize >= 56;
        alpha = Channel(hasAlphaMask ? rd32(b + 66) : 0);
    }
    if (pixelOffset < headersEnd)
        return fail(error, "BMP pixel data offset " + std::to_string(pixelOffset) + " points into its headers");

    const std::uint64_t bytesPerPixel = bpp / 8;
    const std::uint64_t stride = (std::uint64_t(width) * bytesPerPixel + 3) & ~std::uint64_t(3);
    // The last row need not carry its padding; some writers drop it.
    const std::uint64_t needed = stride * (std::uint64_t(height) - 1) + std::uint64_t(width) * bytesPerPixel;
    if (pixelOffset > size || size - pixelOffset < needed)
        return fail(error, "truncated BMP: pixel data needs " + std::to_string(needed) + " bytes at offset " +
                               std::to_string(pixelOffset) + ", file has " + std::to_string(size));

    Image img = Image::rgba8(int(width), int(height));
    bool anyAlpha = false;
    for (std::int64_t y = 0; y < height; ++y) {
        const std::int64_t fileRow = topDown ? y : height - 1 - y;
        const std::uint8_t* src = b + pixelOffset + std::uint64_t(fileRow) * stride;
        std::uint8_t* dst = img.u8.data() + std::size_t(y) * std::size_t(width) * 4;
        for (std::int64_t x = 0; x < width; ++x, dst += 4) {
            if (bpp == 24) {
                const std::uint8_t* p = src + x * 3;
                dst[0] = p[2], dst[1] = p[1], dst[2] = p[0], dst[3] = 255;
            } else {
                const std::uint32_t px = rd32(src + x * 4);
                dst[0] = red.get(px), dst[1] = green.get(px), dst[2] = blue.get(px);
                dst[3] = alpha.mask ? alpha.get(px) : 255;
                anyAlpha |= dst[3] != 0;
            }
        }
    }
    // Many tools write 32-bit BMP with the alpha byte left at zero; an
    // invisible picture is never what they meant.
    if (bpp == 32 && !anyAlpha)
        for (std::size_t i = 3; i < img.u8.size(); i += 4) img.u8[i] = 255;
    out = std::move(img);
    return true;
}

}  // namespace glimmer
