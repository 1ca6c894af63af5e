// Radiance .hdr, read with every count checked (stb's reader loops forever
// on a truncated run-length scanline). Header lines up to a blank line,
// FORMAT=32-bit_rle_rgbe, then "-Y height +X width"; scanlines flat RGBE or
// new-style run-length (2 2 hi lo, then each channel in runs).
#include <cmath>
#include <cstring>
#include <string>

#include "image/sniff.h"

namespace glimmer {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

struct Cursor {
    const std::uint8_t* p;
    std::size_t left;
};

// One header line without its newline; false at the end of the file or when
// the header runs past kMaxHeaderBytes.
bool headerLine(Cursor& c, std::size_t& used, std::string& line) {
    line.clear();
    while (c.left > 0) {
        char ch = char(*c.p++);
        --c.left;
        if (++used > kMaxHeaderBytes) return false;
        if (ch == '\n') return true;
        line += ch;
    }
    return false;
}

bool parseInt(const std::string& s, std::size_t& at, std::int64_t& v) {
    std::size_t start = at;
    v = 0;
    while (at < s.size() && s[at] >= '0' && s[at] <= '9' && at - start < 9) v = v * 10 + (s[at++] - '0');
    return at > start && (at >= s.size() || s[at] < '0' || s[at] > '9');
}

void rgbeToFloat(const std::uint8_t* rgbe, float* out) {
    if (rgbe[3] == 0) {
        out[0] = out[1] = out[2] = 0.f;
    } else {
        // As stb_image and Radiance itself: mantissa * 2^(e - 136).
        float f = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
        out[0] = rgbe[0] * f;
        out[1] = rgbe[1] * f;
        out[2] = rgbe[2] * f;
    }
    out[3] = 1.f;
}

}  // namespace

bool decodeHdr(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error) {
    Cursor c{bytes.data(), bytes.size()};
    std::size_t used = 0;
    std::string line;
    if (!headerLine(c, used, line) || (line != "#?RADIANCE" && line != "#?RGBE")) {
        error = "not a Radiance HDR file";
        return false;
    }
    bool format = false;
    for (;;) {
        if (!headerLine(c, used, line)) {
            error = "truncated or oversized Radiance header";
            return false;
        }
        if (line.empty()) break;
        if (line == "FORMAT=32-bit_rle_rgbe") format = true;
        else if (line.rfind("FORMAT=", 0) == 0) {
            error = "unsupported Radiance format '" + line.substr(7, 40) + "' (only 32-bit_rle_rgbe)";
            return false;
        }
    }
    if (!format) {
        error = "Radiance header has no FORMAT=32-bit_rle_rgbe line";
        return false;
    }
    std::int64_t w = 0, h = 0;
    std::size_t at = 3;
    if (!headerLine(c, used, line) || line.rfind("-Y ", 0) != 0 || !parseInt(line, at, h) ||
        line.compare(at, 4, " +X ") != 0 || !parseInt(line, at += 4, w) || at != line.size()) {
        error = "unsupported Radiance resolution line (only \"-Y height +X width\")";
        return false;
    }
    if (!checkImageSize(w, h, error)) return false;
    const std::size_t width = std::size_t(w), height = std::size_t(h);
    // Even fully run-length coded, a scanline takes its 4-byte head and 2
    // bytes for each run of at most 127 in each of 4 channels: a file too
    // short for its size is refused before the picture is allocated.
    const bool mayRle = width >= 8 && width < 0x8000;
    const std::size_t minScan = mayRle ? 4 + 8 * ((width + 126) / 127) : width * 4;
    if (c.left / height < minScan) {
        error = "truncated Radiance HDR: " + std::to_string(c.left) + " bytes of pixels for " +
                std::to_string(width) + "x" + std::to_string(height);
        return false;
    }
    Image img = Image::rgbaF32(int(width), int(height));
    std::vector<std::uint8_t> scan(width * 4);
    auto truncated = [&](std::size_t y) {
        error = "truncated Radiance HDR at scanline " + std::to_string(y + 1) + " of " + std::to_string(height);
        return false;
    };
    for (std::size_t y = 0; y < height; ++y) {
        const bool rle = width >= 8 && width < 0x8000 && c.left >= 4 && c.p[0] == 2 && c.p[1] == 2 &&
                         (c.p[2] & 0x80) == 0;
        if (rle) {
            if ((std::size_t(c.p[2]) << 8 | c.p[3]) != width) {
                error = "Radiance HDR scanline " + std::to_string(y + 1) + " has the wrong length";
                return false;
            }
            c.p += 4;
            c.left -= 4;
            for (std::size_t ch = 0; ch < 4; ++ch) {
                std::size_t x = 0;
                while (x < width) {
                    if (c.left < 1) return truncated(y);
                    std::size_t count = *c.p++;
                    --c.left;
                    if (count > 128) {
                        count -= 128;
                        if (count > width - x) {
                            error = "Radiance HDR run overflows scanline " + std::to_string(y + 1);
                            return false;
                        }
                        if (c.left < 1) return truncated(y);
                        std::uint8_t v = *c.p++;
                        --c.left;
                        for (std::size_t k = 0; k < count; ++k) scan[(x + k) * 4 + ch] = v;
                    } else {
                        if (count == 0 || count > width - x) {
                            error = "Radiance HDR run overflows scanline " + std::to_string(y + 1);
                            return false;
                        }
                        if (c.left < count) return truncated(y);
                        for (std::size_t k = 0; k < count; ++k) scan[(x + k) * 4 + ch] = c.p[k];
                        c.p += count;
                        c.left -= count;
                    }
                    x += count;
                }
            }
        } else {
            if (c.left < width * 4) return truncated(y);
            std::memcpy(scan.data(), c.p, width * 4);
            c.p += width * 4;
            c.left -= width * 4;
        }
        float* row = img.f32.data() + y * width * 4;
        for (std::size_t x = 0; x < width; ++x) rgbeToFloat(&scan[x * 4], row + x * 4);
    }
    out = std::move(img);
    return true;
}

}  // namespace glimmer
