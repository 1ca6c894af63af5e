#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

using namespace glimmer;
using Bytes = std::vector<std::uint8_t>;

namespace {

void add32(Bytes& b, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(std::uint8_t(v >> (8 * i)));
}
void addF(Bytes& b, float f) { add32(b, std::bit_cast<std::uint32_t>(f)); }

}  // namespace

TEST(Tex, BytesBottomRowFirst) {
    Bytes file;
    add32(file, 2);  // width
    add32(file, 3);  // height
    // File rows: bottom (row 2 of the Image) first.
    for (int fileRow = 0; fileRow < 3; ++fileRow)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < 4; ++c) file.push_back(std::uint8_t(100 * fileRow + 10 * x + c));
    Image img;
    std::string error;
    ASSERT_TRUE(decodeTex2D(file, img, error)) << error;
    ASSERT_EQ(img.type, Image::Type::U8);
    ASSERT_EQ(img.width, 2);
    ASSERT_EQ(img.height, 3);
    const Bytes expected = {200, 201, 202, 203, 210, 211, 212, 213,  // top = last in file
                            100, 101, 102, 103, 110, 111, 112, 113,
                            0,   1,   2,   3,   10,  11,  12,  13};
    EXPECT_EQ(img.u8, expected);
}

TEST(Tex, FloatsBottomRowFirst) {
    Bytes file;
    add32(file, 1);
    add32(file, 2);
    for (float f : {0.5f, -1.0f, 2.25f, 1.0f}) addF(file, f);   // bottom
    for (float f : {10.0f, 0.0f, 1e-3f, 0.75f}) addF(file, f);  // top
    ASSERT_EQ(file.size(), 8u + 2u * 16u);
    Image img;
    std::string error;
    ASSERT_TRUE(decodeTex2D(file, img, error)) << error;
    ASSERT_EQ(img.type, Image::Type::F32);
    const std::vector<float> expected = {10.0f, 0.0f, 1e-3f, 0.75f, 0.5f, -1.0f, 2.25f, 1.0f};
    EXPECT_EQ(img.f32, expected);
    EXPECT_TRUE(img.u8.empty());
}

TEST(Tex, WrongSizeNamesExpectedSizes) {
    Bytes file;
    add32(file, 4);
    add32(file, 2);
    file.resize(8 + 4 * 2 * 4 + 1);
    Image img;
    std::string error;
    EXPECT_FALSE(decodeTex2D(file, img, error));
    EXPECT_EQ(error, ".tex file is 41 bytes; a 4x2 texture needs 40 (RGBA bytes) or 136 (RGBA float32)");
}

TEST(Tex, BadHeaders) {
    Image img;
    std::string error;
    EXPECT_FALSE(decodeTex2D({1, 0, 0}, img, error));
    EXPECT_EQ(error, "truncated .tex: needs 8 bytes of sizes, file has 3");
    Bytes file;
    add32(file, 0xFFFFFFFFu);
    add32(file, 2);
    EXPECT_FALSE(decodeTex2D(file, img, error));
    EXPECT_EQ(error, ".tex has an unusable size -1");
    file.clear();
    add32(file, 0x7FFFFFFF);
    add32(file, 0x7FFFFFFF);
    EXPECT_FALSE(decodeTex2D(file, img, error));  // overflow-prone sizes are refused
    EXPECT_EQ(error, ".tex has an unusable size 2147483647x2147483647");
}

TEST(Tex, Volume) {
    Bytes file;
    add32(file, 2);
    add32(file, 1);
    add32(file, 2);
    for (int i = 0; i < 16; ++i) file.push_back(std::uint8_t(i));
    Volume v;
    std::string error;
    ASSERT_TRUE(decodeTex3D(file, v, error)) << error;
    EXPECT_EQ(v.width, 2);
    EXPECT_EQ(v.height, 1);
    EXPECT_EQ(v.depth, 2);
    EXPECT_EQ(v.type, Image::Type::U8);
    EXPECT_EQ(v.u8, Bytes(file.begin() + 12, file.end()));

    Bytes ffile;
    add32(ffile, 1);
    add32(ffile, 1);
    add32(ffile, 1);
    for (float f : {1.5f, 2.5f, 3.5f, 4.5f}) addF(ffile, f);
    ASSERT_TRUE(decodeTex3D(ffile, v, error)) << error;
    EXPECT_EQ(v.type, Image::Type::F32);
    EXPECT_EQ(v.f32, (std::vector<float>{1.5f, 2.5f, 3.5f, 4.5f}));

    ffile.pop_back();
    EXPECT_FALSE(decodeTex3D(ffile, v, error));
    EXPECT_EQ(error, ".tex file is 27 bytes; a 1x1x1 texture needs 16 (RGBA bytes) or 28 (RGBA float32)");
}
