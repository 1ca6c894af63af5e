// The PNG writer (src/image/png_write.cpp): every level decodes to the very
// bytes it was given, through the project's loader and through libpng.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <png.h>

#include "image/image.h"
#include "image/png_stream.h"
#include "image/test_images.h"

using namespace glimmer;
namespace fs = std::filesystem;

// The PNG writer takes a thread a strip, up to as many as
// std::thread::hardware_concurrency() says; libstdc++ answers that with
// glibc's get_nprocs(). Defined here, in the test program, get_nprocs is
// found before glibc's, so a test can pretend to have any number of cores
// (0: the real answer).
namespace {
std::atomic<int> gPretendCores{0};
}  // namespace

extern "C" int get_nprocs() noexcept {
    if (int n = gPretendCores.load()) return n;
    static const auto real = reinterpret_cast<int (*)()>(dlsym(RTLD_NEXT, "get_nprocs"));
    return real ? real() : 1;
}

namespace {

// A picture with what rendered pictures have: smooth gradients, flat areas,
// hard edges, noise, and alpha that is not all 255.
Image testPicture(int w, int h) {
    Image img = makeNoiseImage(w, h, 7);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.u8.data() + (std::size_t(y) * w + x) * 4;
            if (y < h / 3) {  // a gradient
                p[0] = std::uint8_t(x * 255 / std::max(1, w - 1));
                p[1] = std::uint8_t(y * 255 / std::max(1, h - 1));
                p[2] = 40;
                p[3] = 255;
            } else if (y < 2 * h / 3 && x < w / 2) {  // flat, then noise in the rest
                p[0] = p[1] = p[2] = 0;
                p[3] = std::uint8_t(x & 1 ? 255 : 0);
            }
        }
    return img;
}

std::string tempFile(const std::string& name) {
    return (fs::temp_directory_path() /
            ("glimmer-pngw-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" + name))
        .string();
}

// libpng checks every CRC and zlib every Adler-32: a stricter reader than stb.
bool decodeWithLibpng(const std::vector<std::uint8_t>& bytes, Image& out, std::string& why) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
        why = image.message;
        return false;
    }
    image.format = PNG_FORMAT_RGBA;
    out = Image::rgba8(int(image.width), int(image.height));
    if (!png_image_finish_read(&image, nullptr, out.u8.data(), 0, nullptr)) {
        why = image.message;
        return false;
    }
    return true;
}

}  // namespace

class PngWriteLevels : public ::testing::TestWithParam<int> {};

TEST_P(PngWriteLevels, DecodedPixelsEqualTheImage) {
    const int level = GetParam();
    // 1x1; one strip; several strips with a short last one (700 * 4 bytes a
    // row, 374 rows a strip); and rows wider than a strip.
    for (auto [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {17, 9}, {700, 800}, {300000, 2}}) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " level " + std::to_string(level));
        const Image src = testPicture(w, h);
        const std::string path = tempFile(std::to_string(level) + "-" + std::to_string(w) + ".png");
        std::string why;
        ASSERT_TRUE(writePng(path, src, why, level)) << why;
        if (w <= 16384) {  // the loader's limit (a side); libpng below reads the wide one
            Image back;
            ASSERT_TRUE(loadImage(path, back, why)) << why;
            ASSERT_EQ(back.type, Image::Type::U8);
            EXPECT_EQ(back.width, w);
            EXPECT_EQ(back.height, h);
            EXPECT_TRUE(back.u8 == src.u8);
        }
        fs::remove(path);
        Image strict;
        ASSERT_TRUE(decodeWithLibpng(encodePng(src, level), strict, why)) << why;
        EXPECT_TRUE(strict.u8 == src.u8);
    }
}

INSTANTIATE_TEST_SUITE_P(EveryLevel, PngWriteLevels, ::testing::Range(0, 10));

TEST(PngWrite, TheDefaultLevelIsAValidPngThatLibpngReads) {
    const Image src = testPicture(300, 200);
    const std::string path = tempFile("default.png");
    std::string why;
    ASSERT_TRUE(writePng(path, src, why)) << why;
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(readFileBytes(path, bytes, why)) << why;
    fs::remove(path);
    EXPECT_EQ(bytes, encodePng(src, kDefaultPngLevel));
    EXPECT_EQ(bytes, encodePng(src));
    Image back;
    ASSERT_TRUE(decodeWithLibpng(bytes, back, why)) << why;
    EXPECT_TRUE(back.u8 == src.u8);
}

TEST(PngWrite, HigherLevelsMakeSmallerFiles) {
    const Image src = testPicture(512, 512);
    const auto stored = encodePng(src, 0).size(), fast = encodePng(src, 1).size(), best = encodePng(src, 9).size();
    EXPECT_GT(stored, src.u8.size());  // level 0 stores
    EXPECT_LT(fast, stored);
    EXPECT_LE(best, fast);
}

TEST(PngWrite, TheBytesDoNotDependOnTheCores) {
    // Strips are a fixed number of rows (409 of 640 pixels here: ten strips),
    // so the file is the same whether one thread encodes every strip or
    // several share them, and libpng reads it back exactly.
    const Image src = testPicture(640, 4000);
    struct Pretend {
        explicit Pretend(int n) { gPretendCores = n; }
        ~Pretend() { gPretendCores = 0; }
    };
    std::vector<std::uint8_t> one[2];
    {
        Pretend cores(1);
        ASSERT_EQ(std::thread::hardware_concurrency(), 1u)
            << "this C++ library does not ask get_nprocs(): the test cannot set the writer's threads";
        one[0] = encodePng(src, 1);
        one[1] = encodePng(src, 6);
    }
    for (int n : {2, 3, 7, 16}) {
        Pretend cores(n);
        ASSERT_EQ(std::thread::hardware_concurrency(), unsigned(n));
        EXPECT_EQ(encodePng(src, 1), one[0]) << n << " threads";
        EXPECT_EQ(encodePng(src, 6), one[1]) << n << " threads";
    }
    Image back;
    std::string why;
    ASSERT_TRUE(decodeWithLibpng(one[1], back, why)) << why;
    EXPECT_TRUE(back.u8 == src.u8);
}

TEST(PngWrite, LevelOutOfRangeIsRefused) {
    const Image src = testPicture(4, 4);
    std::string why;
    const std::string path = tempFile("bad-level.png");
    EXPECT_FALSE(writePng(path, src, why, 10));
    EXPECT_EQ(why, "writePng: level 10 is not between 0 and 9");
    EXPECT_FALSE(writePng(path, src, why, -1));
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(encodePng(src, 10).empty());
}
