// Pictures in memory and on disk. Row 0 is the TOP of the picture, as in
// every file format; the renderer flips when it talks to OpenGL (t = 0 is
// the bottom there). No OpenGL here.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace glimmer {

struct Image {
    enum class Type { U8, F32 };
    int width = 0;
    int height = 0;
    Type type = Type::U8;
    std::vector<std::uint8_t> u8;  // RGBA, 4 bytes a texel, when type == U8
    std::vector<float> f32;        // RGBA, 4 floats a texel, when type == F32

    static Image rgba8(int w, int h);
    static Image rgbaF32(int w, int h);
    bool empty() const { return width == 0 || height == 0; }
};

// Loads BMP (24/32-bit, v3..v5 headers, padded rows, any size), PNG, JPEG,
// Radiance .hdr and glman's raw .tex (two little-endian int32 sizes, then RGBA
// texels as bytes or float32, told apart by the file size). Chooses the reader
// by the file's contents, then its extension. On failure returns false and
// sets `error` to a one-line reason ("not a BMP file", "truncated ...").
bool loadImage(const std::string& path, Image& out, std::string& error);

// In-memory readers, used by loadImage and by tests.
bool decodeBmp(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error);
bool decodeTex2D(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error);

// Writers. PNG and BMP take U8 images (RGBA; BMP is written as 24-bit).
// PNG: `level` is zlib's, 0 (stored, the fastest, the largest) to 9 (the
// smallest); every level decodes to the same pixels. The default, 3, is the
// last of zlib's fast levels: on rendered pictures as quick as 1 and about a
// quarter smaller (docs/PERFORMANCE.md, "Writing the picture").
constexpr int kDefaultPngLevel = 3;
bool writePng(const std::string& path, const Image& img, std::string& error, int level = kDefaultPngLevel);
bool writeBmp(const std::string& path, const Image& img, std::string& error);
std::vector<std::uint8_t> encodeBmp(const Image& img);
// Float pictures: Radiance .hdr (RGBE, through stb) and PFM (32-bit float
// RGB, bottom row first as the format says). Both take U8 or F32 images.
bool writeHdr(const std::string& path, const Image& img, std::string& error);
bool writePfm(const std::string& path, const Image& img, std::string& error);
// 16-bit PNG through libpng, values clamped to 0..1 and tagged linear.
bool writePng16(const std::string& path, const Image& img, std::string& error);
// OpenEXR through tinyexr (Debian's libtinyexr): RGBA float32, ZIP.
bool writeExr(const std::string& path, const Image& img, std::string& error);
// Chooses the writer by the extension: .png (8-bit for U8 images, 16-bit for
// F32 ones), .bmp, .hdr, .pfm, .exr.
bool writeImage(const std::string& path, const Image& img, std::string& error);

// glman's 3-D raw .tex: three little-endian int32 sizes (w, h, d), then
// w*h*d RGBA texels as bytes or float32 (told apart by the file size), in
// OpenGL order: x fastest, then y from the bottom row, then z. Kept in that
// order, since volumes go straight to glTexImage3D.
struct Volume {
    int width = 0;
    int height = 0;
    int depth = 0;
    Image::Type type = Image::Type::U8;
    std::vector<std::uint8_t> u8;
    std::vector<float> f32;
};
bool decodeTex3D(const std::vector<std::uint8_t>& bytes, Volume& out, std::string& error);

bool readFileBytes(const std::string& path, std::vector<std::uint8_t>& out, std::string& error);

}  // namespace glimmer
