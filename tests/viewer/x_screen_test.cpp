// The X Window Dump reader the window test uses, on hand-made dumps.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "x_screen.h"

using namespace glimmer_viewer;
using glimmer::Image;

namespace {

// The dump reader on two hand-made dumps, 2x1 pixels, one of each byte order.
std::vector<std::uint8_t> xwd(std::uint32_t byteOrder, std::vector<std::uint8_t> pixels) {
    std::vector<std::uint32_t> h = {100 + 4, 7, 2, 24, 2, 1, 0, byteOrder, 32, byteOrder, 32, 32, 8, 4,
                                    0xff0000, 0xff00, 0xff, 8, 256, 1, 2, 1, 0, 0, 0};
    std::vector<std::uint8_t> b;
    for (auto v : h)
        for (int s = 24; s >= 0; s -= 8) b.push_back(std::uint8_t(v >> s));
    for (char c : std::string("win", 4)) b.push_back(std::uint8_t(c));
    for (int i = 0; i < 12; ++i) b.push_back(0);  // one colormap entry, unused for TrueColor
    b.insert(b.end(), pixels.begin(), pixels.end());
    return b;
}

TEST(XScreen, DecodesXwdInEitherByteOrder) {
    Image img;
    std::string why;
    ASSERT_TRUE(decodeXwd(xwd(0, {0x30, 0x20, 0x10, 0, 0xff, 0x00, 0x80, 0}), img, why)) << why;
    ASSERT_EQ(img.width, 2);
    ASSERT_EQ(img.height, 1);
    EXPECT_EQ(std::vector<std::uint8_t>(img.u8.begin(), img.u8.end()),
              (std::vector<std::uint8_t>{0x10, 0x20, 0x30, 255, 0x80, 0x00, 0xff, 255}));
    ASSERT_TRUE(decodeXwd(xwd(1, {0, 0x10, 0x20, 0x30, 0, 0x80, 0x00, 0xff}), img, why)) << why;
    EXPECT_EQ(std::vector<std::uint8_t>(img.u8.begin(), img.u8.end()),
              (std::vector<std::uint8_t>{0x10, 0x20, 0x30, 255, 0x80, 0x00, 0xff, 255}));
    auto truncated = xwd(0, {0x30, 0x20, 0x10, 0});
    EXPECT_FALSE(decodeXwd(truncated, img, why));
    EXPECT_NE(why.find("truncated"), std::string::npos) << why;
}

// Xvfb on a display it picks, read back whole: the size asked for, and the
// black root window.
TEST(XScreen, CapturesItsOwnScreen) {
    VirtualScreen screen(320, 200);
    ASSERT_FALSE(screen.display().empty()) << screen.why();
    Image img;
    std::string why;
    ASSERT_TRUE(screen.capture(img, why)) << why;
    ASSERT_EQ(img.width, 320);
    ASSERT_EQ(img.height, 200);
    EXPECT_EQ(std::vector<std::uint8_t>(img.u8.begin(), img.u8.begin() + 4), (std::vector<std::uint8_t>{0, 0, 0, 255}));
}

}  // namespace
