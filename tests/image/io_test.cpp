#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/test_images.h"

#include <unistd.h>

#include <cstdlib>

#include <tinyexr.h>
#include <stb/stb_image.h>

using namespace glimmer;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("glimmer-image-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& b) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

}  // namespace

TEST(ImageIo, PngRoundTripThroughStb) {
    TempDir dir;
    Image src = makeNoiseImage(17, 9, 3);
    src.u8[3] = 7;  // a non-opaque texel: PNG keeps alpha
    std::string error;
    ASSERT_TRUE(writePng(dir / "noise.png", src, error)) << error;
    Image back;
    ASSERT_TRUE(loadImage(dir / "noise.png", back, error)) << error;
    EXPECT_EQ(back.type, Image::Type::U8);
    EXPECT_EQ(back.width, 17);
    EXPECT_EQ(back.height, 9);
    EXPECT_EQ(back.u8, src.u8);
}

TEST(ImageIo, WritePngRefusesFloat) {
    TempDir dir;
    std::string error;
    EXPECT_FALSE(writePng(dir / "f.png", Image::rgbaF32(2, 2), error));
    EXPECT_NE(error.find("8-bit"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(dir / "f.png"));
}

TEST(ImageIo, LoadImageChoosesReaderByContent) {
    TempDir dir;
    const Image grid = makeGridImage(40, 24);
    std::string error;
    // BMP contents under a misleading name: the magic bytes win.
    ASSERT_TRUE(writeBmp(dir / "grid.png", grid, error)) << error;
    Image back;
    ASSERT_TRUE(loadImage(dir / "grid.png", back, error)) << error;
    EXPECT_EQ(back.u8, grid.u8);

    // .tex has no magic: the extension decides.
    std::vector<std::uint8_t> tex = {1, 0, 0, 0, 1, 0, 0, 0, 9, 8, 7, 6};
    writeBytes(dir / "one.tex", tex);
    ASSERT_TRUE(loadImage(dir / "one.tex", back, error)) << error;
    EXPECT_EQ(back.u8, (std::vector<std::uint8_t>{9, 8, 7, 6}));

    writeBytes(dir / "junk.bmp", {'B', 'X', 1, 2, 3});
    EXPECT_FALSE(loadImage(dir / "junk.bmp", back, error));
    EXPECT_NE(error.find("junk.bmp"), std::string::npos) << error;

    writeBytes(dir / "bad.bmp", {'B', 'M', 1, 2, 3});
    EXPECT_FALSE(loadImage(dir / "bad.bmp", back, error));
    EXPECT_EQ(error, dir / "bad.bmp" + ": truncated BMP: file header needs 18 bytes, file has 5");

    EXPECT_FALSE(loadImage(dir / "missing.png", back, error));
    EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
}

TEST(ImageIo, LoadsRadianceHdrAsFloat) {
    TempDir dir;
    // One flat (uncompressed) RGBE texel: mantissas 128,64,32 exponent 129 -> 1.0, 0.5, 0.25.
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n";
    std::vector<std::uint8_t> file(header.begin(), header.end());
    for (std::uint8_t v : {128, 64, 32, 129}) file.push_back(v);
    writeBytes(dir / "one.hdr", file);
    Image img;
    std::string error;
    ASSERT_TRUE(loadImage(dir / "one.hdr", img, error)) << error;
    ASSERT_EQ(img.type, Image::Type::F32);
    ASSERT_EQ(img.f32.size(), 4u);
    EXPECT_FLOAT_EQ(img.f32[0], 1.0f);
    EXPECT_FLOAT_EQ(img.f32[1], 0.5f);
    EXPECT_FLOAT_EQ(img.f32[2], 0.25f);
    EXPECT_FLOAT_EQ(img.f32[3], 1.0f);
}

namespace {

// A float picture written as OpenEXR comes back with the same values,
// top row first, including values far above 1.
TEST(ExrWrite, RoundTripsFloatValues) {
    glimmer::Image img = glimmer::Image::rgbaF32(3, 2);
    for (size_t i = 0; i < img.f32.size(); ++i) img.f32[i] = float(i) * 37.5f - 10.f;
    std::string path = (std::filesystem::temp_directory_path() / ("glimmer_exr_" + std::to_string(::getpid()) + ".exr")).string();
    std::string err;
    ASSERT_TRUE(glimmer::writeImage(path, img, err)) << err;
    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* e = nullptr;
    ASSERT_EQ(LoadEXR(&rgba, &w, &h, path.c_str(), &e), 0);
    ASSERT_EQ(w, 3);
    ASSERT_EQ(h, 2);
    for (size_t i = 0; i < img.f32.size(); ++i) EXPECT_EQ(rgba[i], img.f32[i]) << i;
    std::free(rgba);
    std::filesystem::remove(path);
}

TEST(ExrWrite, UnknownExtensionIsNamed) {
    std::string err;
    EXPECT_FALSE(glimmer::writeImage("out.tiff", glimmer::Image::rgba8(1, 1), err));
    EXPECT_EQ(err, "cannot write 'out.tiff': use .png, .hdr, .pfm, .exr or .bmp");
}

}  // namespace

namespace {

// A float picture written as .png becomes a 16-bit PNG: read back through
// stb at 16 bits, each value is the clamped float to within one 16-bit step.
TEST(Png16Write, FloatImagesKeepSixteenBits) {
    glimmer::Image img = glimmer::Image::rgbaF32(4, 1);
    const float v[4] = {0.1234567f, 0.5f, 2.0f, -1.0f};
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 4; ++c) img.f32[size_t(x) * 4 + size_t(c)] = c == 3 ? 1.f : v[x];
    std::string path = (std::filesystem::temp_directory_path() / ("glimmer_png16_" + std::to_string(::getpid()) + ".png")).string();
    std::string err;
    ASSERT_TRUE(glimmer::writeImage(path, img, err)) << err;
    int w = 0, h = 0, n = 0;
    unsigned short* px = stbi_load_16(path.c_str(), &w, &h, &n, 4);
    ASSERT_NE(px, nullptr);
    EXPECT_EQ(stbi_is_16_bit(path.c_str()), 1);
    const double expected[4] = {0.1234567, 0.5, 1.0, 0.0};
    for (int x = 0; x < 4; ++x) EXPECT_NEAR(px[x * 4] / 65535.0, expected[x], 0.5 / 65535.0 + 1e-9) << x;
    stbi_image_free(px);
    std::filesystem::remove(path);
}

}  // namespace
