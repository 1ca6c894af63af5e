// The 8-bit PNG writer: the container written here, the pixels deflated by
// zlib in strips of rows that are compressed at the same time.
//
// Each strip (a fixed number of rows, about 1 MiB of pixels, so the bytes of
// a file do not depend on how many cores wrote it) is filtered and deflated
// on its own, ended with a sync flush so the strips join into one zlib stream
// (as pigz does); the Adler-32s of the strips are combined. The decoded
// pixels are the image's, at every level.
#include "image/png_stream.h"
#include "util/write_file.h"

#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <thread>

namespace glimmer {
namespace {

constexpr std::size_t kStripBytes = std::size_t(1) << 20;  // pixels a strip, before filtering
constexpr std::size_t kMaxIdat = std::size_t(1) << 20;     // bytes an IDAT chunk

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    out.push_back(std::uint8_t(v >> 24));
    out.push_back(std::uint8_t(v >> 16));
    out.push_back(std::uint8_t(v >> 8));
    out.push_back(std::uint8_t(v));
}

void chunk(std::vector<std::uint8_t>& out, const char* type, const std::uint8_t* data, std::size_t n) {
    put32(out, std::uint32_t(n));
    const std::size_t at = out.size();
    out.insert(out.end(), type, type + 4);
    if (n) out.insert(out.end(), data, data + n);
    const uLong crc = crc32(0L, out.data() + at, uInt(n + 4));
    put32(out, std::uint32_t(crc));
}

// Filters one row into `dst` (1 + n bytes): its filter byte, then the
// filtered bytes. `prev` is the row above (nullptr for the first row).
// Level 0 stores rows as they are (filter None); the others use Up (Sub on
// the first row). On the bloom picture Up alone made files as small as
// libpng's per-row choice among the five filters at a third of the time,
// and smaller than stb's (measured: docs/PERFORMANCE.md).
void filterRow(int level, const std::uint8_t* row, const std::uint8_t* prev, std::size_t n, std::uint8_t* dst) {
    constexpr std::size_t bpp = 4;
    if (level == 0) {
        dst[0] = 0;
        std::memcpy(dst + 1, row, n);
    } else if (prev) {
        dst[0] = 2;
        for (std::size_t i = 0; i < n; ++i) dst[1 + i] = std::uint8_t(row[i] - prev[i]);
    } else {
        dst[0] = 1;
        for (std::size_t i = 0; i < bpp && i < n; ++i) dst[1 + i] = row[i];
        for (std::size_t i = bpp; i < n; ++i) dst[1 + i] = std::uint8_t(row[i] - row[i - bpp]);
    }
}

struct Strip {
    int first = 0, rows = 0;
    std::vector<std::uint8_t> deflated;
    uLong adler = 1;
    std::size_t rawBytes = 0;
    bool ok = false;
};

void encodeStrip(const Image& img, int level, bool last, Strip& s) {
    const std::size_t n = std::size_t(img.width) * 4;
    std::vector<std::uint8_t> raw(std::size_t(s.rows) * (n + 1));
    for (int r = 0; r < s.rows; ++r) {
        const int y = s.first + r;
        const std::uint8_t* row = img.u8.data() + std::size_t(y) * n;
        filterRow(level, row, y > 0 ? row - n : nullptr, n, raw.data() + std::size_t(r) * (n + 1));
    }
    s.rawBytes = raw.size();
    s.adler = adler32(1L, raw.data(), uInt(raw.size()));
    z_stream z{};
    // Raw deflate: the zlib header and Adler-32 are written once, around all strips.
    // The default strategy: Z_RLE was slower and larger on the bloom picture.
    if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return;
    s.deflated.resize(deflateBound(&z, uLong(raw.size())) + 16);
    z.next_in = raw.data();
    z.avail_in = uInt(raw.size());
    z.next_out = s.deflated.data();
    z.avail_out = uInt(s.deflated.size());
    const int rc = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
    s.ok = last ? rc == Z_STREAM_END : (rc == Z_OK && z.avail_in == 0 && z.avail_out > 0);  // all flushed
    s.deflated.resize(z.total_out);
    deflateEnd(&z);
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Image& img, int level) {
    std::vector<std::uint8_t> out;
    if (img.type != Image::Type::U8 || img.empty() || img.u8.size() != std::size_t(img.width) * std::size_t(img.height) * 4 ||
        level < 0 || level > 9)
        return out;
    const std::size_t rowBytes = std::size_t(img.width) * 4;
    const int stripRows = int(std::clamp<std::size_t>(kStripBytes / rowBytes, 1, std::size_t(img.height)));
    std::vector<Strip> strips;
    for (int y = 0; y < img.height; y += stripRows) {
        Strip s;
        s.first = y;
        s.rows = std::min(stripRows, img.height - y);
        strips.push_back(std::move(s));
    }
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const unsigned workers = unsigned(std::min<std::size_t>({strips.size(), cores, 16}));
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < strips.size();)
            encodeStrip(img, level, i + 1 == strips.size(), strips[i]);
    };
    std::vector<std::thread> pool;
    try {
        for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
    } catch (const std::system_error&) {
        // No more threads to be had: those started and this one do it all.
    }
    work();
    for (auto& t : pool) t.join();

    std::size_t total = 2 + 4;
    uLong adler = 1;
    for (const auto& s : strips) {
        if (!s.ok) return out;
        total += s.deflated.size();
        adler = adler32_combine(adler, s.adler, z_off_t(s.rawBytes));
    }
    std::vector<std::uint8_t> z;
    z.reserve(total);
    // CMF 0x78 (deflate, 32K window); FLG with the level hint and the check bits.
    const std::uint8_t flevel = level == 0 ? 0 : level <= 5 ? 1 : level == 6 ? 2 : 3;
    std::uint16_t header = std::uint16_t(0x78 << 8 | flevel << 6);
    header = std::uint16_t(header + (31 - header % 31) % 31);
    z.push_back(std::uint8_t(header >> 8));
    z.push_back(std::uint8_t(header));
    for (const auto& s : strips) z.insert(z.end(), s.deflated.begin(), s.deflated.end());
    put32(z, std::uint32_t(adler));

    static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    out.reserve(z.size() + z.size() / kMaxIdat * 12 + 64);
    out.insert(out.end(), signature, signature + 8);
    std::vector<std::uint8_t> ihdr;
    put32(ihdr, std::uint32_t(img.width));
    put32(ihdr, std::uint32_t(img.height));
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive filters, not interlaced
    chunk(out, "IHDR", ihdr.data(), ihdr.size());
    for (std::size_t at = 0; at < z.size(); at += kMaxIdat)
        chunk(out, "IDAT", z.data() + at, std::min(kMaxIdat, z.size() - at));
    chunk(out, "IEND", nullptr, 0);
    return out;
}

bool writePng(const std::string& path, const Image& img, std::string& error, int level) {
    if (img.type != Image::Type::U8) {
        error = "writePng needs an 8-bit image; " + path + " would be float";
        return false;
    }
    if (img.empty() || img.u8.size() != std::size_t(img.width) * img.height * 4) {
        error = "writePng: empty or inconsistent image";
        return false;
    }
    if (level < 0 || level > 9) {
        error = "writePng: level " + std::to_string(level) + " is not between 0 and 9";
        return false;
    }
    const std::vector<std::uint8_t> bytes = encodePng(img, level);
    if (bytes.empty()) {
        error = "cannot encode " + path + " as PNG";
        return false;
    }
    // A temporary file renamed over the output: a full disk keeps the last good picture.
    return writeBytesReplacing(path, bytes.data(), bytes.size(), error);
}

}  // namespace glimmer
