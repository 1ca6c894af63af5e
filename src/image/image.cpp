#include "image/image.h"
#include "image/float_pixels.h"
#include "image/sniff.h"
#include "util/read_file.h"
#include "util/write_file.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <cctype>
#include <cstring>
#include <fstream>
#include <memory>

namespace glimmer {

Image Image::rgba8(int w, int h) {
    Image img;
    img.width = w;
    img.height = h;
    img.type = Type::U8;
    img.u8.assign(std::size_t(w) * std::size_t(h) * 4, 0);
    return img;
}

Image Image::rgbaF32(int w, int h) {
    Image img;
    img.width = w;
    img.height = h;
    img.type = Type::F32;
    img.f32.assign(std::size_t(w) * std::size_t(h) * 4, 0.0f);
    return img;
}

bool readFileBytes(const std::string& path, std::vector<std::uint8_t>& out, std::string& error) {
    if (!readRegularFile(path, kMaxInputFileBytes, out, error)) {
        // "cannot open PATH" as before; "PATH is not a regular file", ...
        error = error.rfind("cannot open", 0) == 0 ? "cannot open " + path : path + " " + error;
        return false;
    }
    return true;
}

bool loadImage(const std::string& path, Image& out, std::string& error) {
    std::vector<std::uint8_t> bytes;
    if (!readFileBytes(path, bytes, error)) return false;
    bool ok = false;
    switch (sniffImage(bytes, path)) {
    case ImageFormat::Bmp: ok = decodeBmp(bytes, out, error); break;
    case ImageFormat::Png:
    case ImageFormat::Jpeg: ok = decodePngJpeg(bytes, out, error); break;
    case ImageFormat::Hdr: ok = decodeHdr(bytes, out, error); break;
    case ImageFormat::Tex: ok = decodeTex2D(bytes, out, error); break;
    case ImageFormat::Unknown:
        error = "not an image Glimmer reads (BMP, PNG, JPEG, Radiance .hdr or raw .tex)";
        break;
    }
    if (ok && out.empty()) {
        ok = false;
        error = "zero-size image";
    }
    if (!ok) error = path + ": " + error;
    return ok;
}

// writePng: src/image/png_write.cpp.

std::vector<std::uint8_t> encodeBmp(const Image& img) {
    const std::size_t texels = std::size_t(std::max(img.width, 0)) * std::size_t(std::max(img.height, 0));
    const std::size_t have = img.type == Image::Type::U8 ? img.u8.size() : img.f32.size();
    if (img.empty() || have != texels * 4) return {};  // nothing sane to encode
    const std::uint32_t w = std::uint32_t(img.width);
    const std::uint32_t h = std::uint32_t(img.height);
    const std::uint32_t stride = (w * 3 + 3) & ~3u;
    const std::uint32_t pixelBytes = stride * h;
    const std::uint32_t offset = 14 + 40;
    std::vector<std::uint8_t> b(offset + pixelBytes, 0);
    auto put16 = [&](std::size_t at, std::uint32_t v) {
        b[at] = std::uint8_t(v);
        b[at + 1] = std::uint8_t(v >> 8);
    };
    auto put32 = [&](std::size_t at, std::uint32_t v) {
        put16(at, v);
        put16(at + 2, v >> 16);
    };
    b[0] = 'B';
    b[1] = 'M';
    put32(2, std::uint32_t(b.size()));
    put32(10, offset);
    put32(14, 40);
    put32(18, w);
    put32(22, h);  // positive: bottom-up, the form every reader accepts
    put16(26, 1);
    put16(28, 24);
    put32(30, 0);  // BI_RGB
    put32(34, pixelBytes);
    put32(38, 2835);  // 72 dpi, so viewers show a sane physical size
    put32(42, 2835);
    for (std::uint32_t y = 0; y < h; ++y) {
        std::uint8_t* row = b.data() + offset + std::size_t(h - 1 - y) * stride;
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = (std::size_t(y) * w + x) * 4;
            std::uint8_t r, g, bl;
            if (img.type == Image::Type::U8) {
                r = img.u8[i], g = img.u8[i + 1], bl = img.u8[i + 2];
            } else {
                auto q = [](float f) {
                    return std::uint8_t(std::clamp(f, 0.0f, 1.0f) * 255.0f + 0.5f);
                };
                r = q(img.f32[i]), g = q(img.f32[i + 1]), bl = q(img.f32[i + 2]);
            }
            row[x * 3] = bl;
            row[x * 3 + 1] = g;
            row[x * 3 + 2] = r;
        }
    }
    return b;
}

bool writeBmp(const std::string& path, const Image& img, std::string& error) {
    if (img.type != Image::Type::U8) {
        error = "writeBmp needs an 8-bit image; " + path + " would be float";
        return false;
    }
    const auto bytes = encodeBmp(img);
    if (bytes.empty()) {
        error = "writeBmp: empty or inconsistent image";
        return false;
    }
    return writeBytesReplacing(path, bytes.data(), bytes.size(), error);
}

namespace {

// Any image as float RGBA, row 0 at the top.
std::vector<float> asFloats(const Image& img) {
    if (img.type == Image::Type::F32) return img.f32;
    std::vector<float> f(img.u8.size());
    for (size_t i = 0; i < f.size(); ++i) f[i] = img.u8[i] / 255.f;
    return f;
}

bool consistent(const Image& img) {
    size_t n = size_t(img.width) * size_t(img.height) * 4;
    return img.width > 0 && img.height > 0 && (img.type == Image::Type::F32 ? img.f32.size() : img.u8.size()) == n;
}

}  // namespace

bool floatPixels(const Image& img, const char* writer, std::vector<float>& px, std::string& error) {
    if (!consistent(img)) {
        error = std::string(writer) + ": empty or inconsistent image";
        return false;
    }
    px = asFloats(img);
    return true;
}

bool writeHdr(const std::string& path, const Image& img, std::string& error) {
    std::vector<float> f;
    if (!floatPixels(img, "writeHdr", f, error)) return false;
    return writeReplacing(path, [&](const std::string& target, std::string& why) {
        if (stbi_write_hdr(target.c_str(), img.width, img.height, 4, f.data())) return true;
        why = "cannot write " + path;
        return false;
    }, error);
}

bool writePfm(const std::string& path, const Image& img, std::string& error) {
    std::vector<float> px;
    if (!floatPixels(img, "writePfm", px, error)) return false;
    // "PF" is colour; a negative scale means little-endian floats. PFM
    // stores the bottom row first.
    std::string bytes = "PF\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n-1.0\n";
    const size_t head = bytes.size(), rowBytes = size_t(img.width) * 3 * sizeof(float);
    bytes.resize(head + rowBytes * size_t(img.height));
    std::vector<float> row(size_t(img.width) * 3);
    for (int y = img.height - 1; y >= 0; --y) {
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) row[size_t(x) * 3 + size_t(c)] = px[(size_t(y) * size_t(img.width) + size_t(x)) * 4 + size_t(c)];
        std::memcpy(bytes.data() + head + rowBytes * size_t(img.height - 1 - y), row.data(), rowBytes);
    }
    return writeBytesReplacing(path, bytes.data(), bytes.size(), error);
}

bool writeImage(const std::string& path, const Image& img, std::string& error) {
    auto ext = std::filesystem::path(path).extension().string();
    for (auto& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == ".hdr") return writeHdr(path, img, error);
    if (ext == ".pfm") return writePfm(path, img, error);
    if (ext == ".exr") return writeExr(path, img, error);
    if (ext == ".bmp") return writeBmp(path, img, error);
    if (ext == ".png") return img.type == Image::Type::U8 ? writePng(path, img, error) : writePng16(path, img, error);
    error = "cannot write '" + path + "': use .png, .hdr, .pfm, .exr or .bmp";
    return false;
}

}  // namespace glimmer
