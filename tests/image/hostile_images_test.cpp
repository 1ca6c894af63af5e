// Hostile image files, made here byte by byte: each is refused with a reason,
// quickly, without reading past the file or allocating what its header claims.
#include <gtest/gtest.h>

#include "common/test_folder.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image/cubemap.h"
#include "image/image.h"
#include "image/sniff.h"
#include "util/read_file.h"

using namespace glimmer;
namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<std::uint8_t>;

struct Dir {
    glimmer::testing::TestFolder folder{"glimmer-hostile-"};
    fs::path path = folder.path;
    std::string write(const std::string& name, const Bytes& b) const {
        std::string p = (path / name).string();
        std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
        return p;
    }
};

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

void append(Bytes& b, std::initializer_list<int> v) {
    for (int x : v) b.push_back(std::uint8_t(x));
}

void be32(Bytes& b, std::uint32_t v) { append(b, {int(v >> 24), int(v >> 16 & 255), int(v >> 8 & 255), int(v & 255)}); }

// Loads through the public entry point; fails the test if it takes long
// (the truncated .hdr made stb loop forever).
std::string loadError(const std::string& path) {
    Image img;
    std::string error;
    auto t0 = std::chrono::steady_clock::now();
    bool ok = loadImage(path, img, error);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
    EXPECT_FALSE(ok) << path;
    return error;
}

const std::string kHdrHead = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

}  // namespace

TEST(HostileImages, TruncatedRunLengthHdrIsAnErrorNotALoop) {
    Dir d;
    Bytes b = text(kHdrHead + "-Y 4 +X 8\n");
    append(b, {2, 2, 0, 8, 130, 7});  // one run of 2 in the red channel, then the file ends
    const std::string p = d.write("cut.hdr", b);
    EXPECT_EQ(loadError(p), p + ": truncated Radiance HDR: 6 bytes of pixels for 8x4");
    // Enough bytes for the size check, cut inside a literal run.
    b = text(kHdrHead + "-Y 1 +X 8\n");
    append(b, {2, 2, 0, 8, 8, 1, 2, 3, 4, 5, 6, 7, 8, 5, 1, 2});
    d.write("cut2.hdr", b);
    EXPECT_EQ(loadError((d.path / "cut2.hdr").string()), (d.path / "cut2.hdr").string() +
                                                             ": truncated Radiance HDR at scanline 1 of 1");
}

TEST(HostileImages, HdrRunPastTheScanlineIsRefused) {
    Dir d;
    Bytes b = text(kHdrHead + "-Y 1 +X 8\n");
    append(b, {2, 2, 0, 8, 128 + 9, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    const std::string p = d.write("run.hdr", b);
    EXPECT_EQ(loadError(p), p + ": Radiance HDR run overflows scanline 1");
}

TEST(HostileImages, HdrReaderMatchesStbOnWellFormedRunLengthFiles) {
    Dir d;
    const int w = 37, h = 5;
    std::vector<float> px(size_t(w) * h * 3);
    for (size_t i = 0; i < px.size(); ++i) px[i] = float((i * 7919) % 1000) / 37.f;
    const std::string p = (d.path / "rle.hdr").string();
    ASSERT_TRUE(stbi_write_hdr(p.c_str(), w, h, 3, px.data()));
    Image img;
    std::string error;
    ASSERT_TRUE(loadImage(p, img, error)) << error;
    int sw = 0, sh = 0, n = 0;
    float* ref = stbi_loadf(p.c_str(), &sw, &sh, &n, 4);
    ASSERT_NE(ref, nullptr);
    ASSERT_EQ(img.width, sw);
    ASSERT_EQ(img.height, sh);
    ASSERT_EQ(img.type, Image::Type::F32);
    for (size_t i = 0; i < img.f32.size(); ++i) ASSERT_EQ(img.f32[i], ref[i]) << i;
    stbi_image_free(ref);
}

TEST(HostileImages, ZeroSizeHdrIsAnError) {
    Dir d;
    const std::string p = d.write("zero.hdr", text(kHdrHead + "-Y 0 +X 5\n"));
    EXPECT_EQ(loadError(p), p + ": zero-size image (5x0)");
}

TEST(HostileImages, TgaHeaderNamedPngIsNotDecoded) {
    // 18 bytes of TGA header claiming 65535x65535 truecolour: stb would
    // allocate gigabytes for it.
    Dir d;
    Bytes b;
    append(b, {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 255, 255, 255, 255, 32, 8});
    const std::string p = d.write("fake.png", b);
    EXPECT_EQ(loadError(p), p + ": not an image Glimmer reads (BMP, PNG, JPEG, Radiance .hdr or raw .tex)");
}

TEST(HostileImages, SixteenBitPnmIsNotDecoded) {
    Dir d;
    Bytes b = text("P5\n2 2\n65535\n");
    append(b, {0, 0, 0, 0, 0, 0});  // short of the 8 bytes it needs
    const std::string p = d.write("deep.png", b);
    EXPECT_EQ(loadError(p), p + ": not an image Glimmer reads (BMP, PNG, JPEG, Radiance .hdr or raw .tex)");
}

// The same bytes handed straight to the PNG/JPEG decoder (as the fuzz
// target does): it sniffs them itself, so stb's PNM reader is never reached.
// From the fuzzing campaign: P5, CR as the separator, maxval 5503 (16 bit).
TEST(HostileImages, PngJpegDecoderRefusesWhatIsNotPngOrJpeg) {
    for (const std::string& header : {std::string("P5\n2 2\n65535\n"), std::string("P5\r155\r5503\r0525"),
                                      std::string("GIF89a\x01\x00\x01\x00")}) {
        Bytes b = text(header);
        append(b, {0, 0, 0, 0, 0, 0});
        Image img;
        std::string error;
        EXPECT_FALSE(decodePngJpeg(b, img, error)) << header;
        EXPECT_EQ(error, "not a PNG or JPEG file (by its first bytes)");
        EXPECT_TRUE(img.empty());
    }
}

TEST(HostileImages, HugePngHeaderIsRefusedBeforeDecoding) {
    Dir d;
    Bytes b = text("\x89PNG\r\n\x1a\n");
    be32(b, 13);
    for (char c : std::string("IHDR")) b.push_back(std::uint8_t(c));
    be32(b, 12000);  // small enough for stb's own check, too many texels for Glimmer's
    be32(b, 12000);
    append(b, {8, 6, 0, 0, 0, 0, 0, 0, 0});  // depth, colour type, methods, a CRC nobody checks
    const std::string p = d.write("huge.png", b);
    EXPECT_EQ(loadError(p), p + ": image of 12000x12000 is larger than Glimmer reads (16384 a side, 134217728 texels)");
}

TEST(HostileImages, NonRegularFilesAreRefusedUnread) {
    Dir d;
    EXPECT_EQ(loadError(d.path.string()), d.path.string() + " is a folder, not a file");
    const std::string fifo = (d.path / "pipe.png").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(loadError(fifo), fifo + " is not a regular file");  // and does not wait for a writer
    EXPECT_EQ(loadError("/proc/self/environ"), "/proc/self/environ is not a regular file");
    EXPECT_EQ(loadError("/dev/zero"), "/dev/zero is not a regular file");
    Volume v;
    std::string error;
    EXPECT_FALSE(loadVolume("/proc/self/mem", v, error));
    EXPECT_EQ(error, "/proc/self/mem is not a regular file");
}

TEST(HostileImages, ReadRegularFileKeepsToItsLimit) {
    Dir d;
    const std::string p = d.write("big.bin", Bytes(1000, 7));
    std::string out, error;
    EXPECT_FALSE(readRegularFile(p, 999, out, error));
    EXPECT_EQ(error, "is larger than 999 bytes");
    EXPECT_TRUE(out.empty());
    ASSERT_TRUE(readRegularFile(p, 1000, out, error)) << error;
    EXPECT_EQ(out.size(), 1000u);
}

TEST(HostileImages, SniffingIgnoresTheExtensionExceptForTex) {
    EXPECT_EQ(sniffImage(text("BM...."), "x.png"), ImageFormat::Bmp);
    EXPECT_EQ(sniffImage(text("#?RADIANCE\n"), "x.bmp"), ImageFormat::Hdr);
    EXPECT_EQ(sniffImage(text("GIF89a"), "x.gif"), ImageFormat::Unknown);
    EXPECT_EQ(sniffImage(text("\1\0\0\0"), "x.TEX"), ImageFormat::Tex);
}
