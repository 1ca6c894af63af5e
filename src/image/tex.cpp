// glman's raw .tex: little-endian int32 sizes, then RGBA texels exactly as
// glman passed them to glTexImage2D/3D, so the first row is the bottom one.
#include "image/image.h"

#include <cstring>
#include <string>

namespace glimmer {
namespace {

// 2^36 texels is a terabyte of bytes: beyond any real file, and small enough
// that the byte counts below cannot overflow.
constexpr std::uint64_t kMaxTexels = std::uint64_t(1) << 36;

std::int32_t rdI32(const std::uint8_t* p) {
    return std::int32_t(std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) |
                        (std::uint32_t(p[3]) << 24));
}

// memcpy, not std::bit_cast: Emscripten 3.1.6's libc++ has no bit_cast.
float rdF32(const std::uint8_t* p) {
    std::uint32_t bits = std::uint32_t(rdI32(p));
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

enum class Layout { Bytes, Floats, Bad };

// Reads `n` sizes, and tells from the file size whether texels are bytes or
// floats; on failure `error` names the sizes that would have worked.
Layout readHeader(const std::vector<std::uint8_t>& bytes, int n, int* dims, std::uint64_t& texels,
                  std::string& error) {
    const std::uint64_t header = 4ull * n;
    if (bytes.size() < header) {
        error = "truncated .tex: needs " + std::to_string(header) + " bytes of sizes, file has " +
                std::to_string(bytes.size());
        return Layout::Bad;
    }
    std::string shape;
    texels = 1;
    for (int i = 0; i < n; ++i) {
        dims[i] = rdI32(bytes.data() + 4 * i);
        shape += (i ? "x" : "") + std::to_string(dims[i]);
        if (dims[i] <= 0 || texels * std::uint64_t(dims[i]) > kMaxTexels) {
            error = ".tex has an unusable size " + shape;
            return Layout::Bad;
        }
        texels *= std::uint64_t(dims[i]);
    }
    const std::uint64_t asBytes = header + texels * 4, asFloats = header + texels * 16;
    if (bytes.size() == asBytes) return Layout::Bytes;
    if (bytes.size() == asFloats) return Layout::Floats;
    error = ".tex file is " + std::to_string(bytes.size()) + " bytes; a " + shape + " texture needs " +
            std::to_string(asBytes) + " (RGBA bytes) or " + std::to_string(asFloats) + " (RGBA float32)";
    return Layout::Bad;
}

}  // namespace

bool decodeTex2D(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error) {
    int dims[2];
    std::uint64_t texels = 0;
    const Layout layout = readHeader(bytes, 2, dims, texels, error);
    if (layout == Layout::Bad) return false;
    const int w = dims[0], h = dims[1];
    const std::uint8_t* src = bytes.data() + 8;
    const std::size_t rowValues = std::size_t(w) * 4;
    Image img = layout == Layout::Bytes ? Image::rgba8(w, h) : Image::rgbaF32(w, h);
    for (int y = 0; y < h; ++y) {
        const std::size_t fileRow = std::size_t(h - 1 - y);  // file is bottom row first
        if (layout == Layout::Bytes) {
            std::memcpy(img.u8.data() + y * rowValues, src + fileRow * rowValues, rowValues);
        } else {
            const std::uint8_t* row = src + fileRow * rowValues * 4;
            float* dst = img.f32.data() + y * rowValues;
            for (std::size_t i = 0; i < rowValues; ++i) dst[i] = rdF32(row + 4 * i);
        }
    }
    out = std::move(img);
    return true;
}

bool decodeTex3D(const std::vector<std::uint8_t>& bytes, Volume& out, std::string& error) {
    int dims[3];
    std::uint64_t texels = 0;
    const Layout layout = readHeader(bytes, 3, dims, texels, error);
    if (layout == Layout::Bad) return false;
    Volume v;
    v.width = dims[0], v.height = dims[1], v.depth = dims[2];
    const std::uint8_t* src = bytes.data() + 12;
    if (layout == Layout::Bytes) {
        v.type = Image::Type::U8;
        v.u8.assign(src, src + texels * 4);
    } else {
        v.type = Image::Type::F32;
        v.f32.resize(texels * 4);
        for (std::size_t i = 0; i < v.f32.size(); ++i) v.f32[i] = rdF32(src + 4 * i);
    }
    out = std::move(v);
    return true;
}

}  // namespace glimmer
