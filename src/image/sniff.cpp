#include "image/sniff.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace glimmer {
namespace {

bool startsWith(const std::vector<std::uint8_t>& b, const char* magic, std::size_t n) {
    return b.size() >= n && std::memcmp(b.data(), magic, n) == 0;
}

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                      [](char a, char b) { return std::tolower((unsigned char)b) == a; });
}

}  // namespace

ImageFormat sniffImage(const std::vector<std::uint8_t>& bytes, const std::string& path) {
    if (startsWith(bytes, "BM", 2)) return ImageFormat::Bmp;
    if (startsWith(bytes, "\x89PNG\r\n\x1a\n", 8)) return ImageFormat::Png;
    if (startsWith(bytes, "\xff\xd8\xff", 3)) return ImageFormat::Jpeg;
    if (startsWith(bytes, "#?RADIANCE\n", 11) || startsWith(bytes, "#?RGBE\n", 7)) return ImageFormat::Hdr;
    if (endsWithNoCase(path, ".tex")) return ImageFormat::Tex;  // glman's raw files have no magic
    return ImageFormat::Unknown;
}

const char* imageFormatName(ImageFormat f) {
    switch (f) {
    case ImageFormat::Bmp: return "BMP";
    case ImageFormat::Png: return "PNG";
    case ImageFormat::Jpeg: return "JPEG";
    case ImageFormat::Hdr: return "Radiance HDR";
    case ImageFormat::Tex: return "raw .tex";
    case ImageFormat::Unknown: break;
    }
    return "unknown";
}

bool checkImageSize(std::int64_t w, std::int64_t h, std::string& error) {
    if (w <= 0 || h <= 0) {
        error = "zero-size image (" + std::to_string(w) + "x" + std::to_string(h) + ")";
        return false;
    }
    if (w > kMaxImageSide || h > kMaxImageSide || std::uint64_t(w) * std::uint64_t(h) > kMaxImageTexels) {
        error = "image of " + std::to_string(w) + "x" + std::to_string(h) + " is larger than Glimmer reads (" +
                std::to_string(kMaxImageSide) + " a side, " + std::to_string(kMaxImageTexels) + " texels)";
        return false;
    }
    return true;
}

}  // namespace glimmer
