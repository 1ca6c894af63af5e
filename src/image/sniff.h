// Which image format a file holds, told by its contents (the extension only
// for glman's headerless .tex), and the limits every decoder checks before
// it allocates anything.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// Glimmer reads only the formats it documents; everything else (TGA, GIF,
// PNM, PSD, ... that stb would also try) is refused unread.
enum class ImageFormat { Bmp, Png, Jpeg, Hdr, Tex, Unknown };

ImageFormat sniffImage(const std::vector<std::uint8_t>& bytes, const std::string& path);
const char* imageFormatName(ImageFormat f);

// Largest side and texel count a decoded 2-D image may have (16384 is what
// GPUs take; 2^27 texels is 512 MiB as RGBA8, 2 GiB as float).
constexpr int kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImageTexels = std::uint64_t(1) << 27;

// True when w x h is a usable image size; else false with `error`
// ("zero-size image", "image of 20000x20000 is larger than ...").
bool checkImageSize(std::int64_t w, std::int64_t h, std::string& error);

// PNG and JPEG through stb_image, after their sizes are read and checked
// (stbi_info) so a hostile header cannot make it allocate gigabytes.
bool decodePngJpeg(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error);

// Radiance .hdr (RGBE; flat or new-style run-length scanlines, -Y H +X W),
// a checked reader of Glimmer's own: every count is bounded by what is left
// of the scanline and of the file, so a truncated file is an error, never a
// loop or an over-read.
bool decodeHdr(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error);

}  // namespace glimmer
