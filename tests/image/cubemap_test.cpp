// Cube maps from six files, and glman's raw 3-D .tex read from disk.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/cubemap.h"
#include "image/image.h"

using namespace glimmer;
namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("glimmer-cubemap-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

void writeBytes(const std::string& path, const Bytes& b) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

// A w x h face filled with a colour that names face `i`, with one marked
// texel at the top left so the row order shows.
Image face(int i, int w, int h) {
    Image img = Image::rgba8(w, h);
    for (std::size_t t = 0; t < img.u8.size(); t += 4) {
        img.u8[t] = std::uint8_t(40 * i + 10);
        img.u8[t + 1] = std::uint8_t(200 - 30 * i);
        img.u8[t + 2] = std::uint8_t(7 * i);
        img.u8[t + 3] = 255;
    }
    img.u8[0] = img.u8[1] = img.u8[2] = 255;  // top-left texel white
    return img;
}

// Writes six faces (face i w x h, unless `sizes` says otherwise) as BMPs and
// returns their paths in +x -x +y -y +z -z order.
std::array<std::string, 6> writeFaces(const TempDir& dir, std::array<std::array<int, 2>, 6> sizes) {
    const char* names[6] = {"posx.bmp", "negx.bmp", "posy.bmp", "negy.bmp", "posz.bmp", "negz.bmp"};
    std::array<std::string, 6> paths;
    for (int i = 0; i < 6; ++i) {
        paths[i] = dir / names[i];
        std::string error;
        EXPECT_TRUE(writeBmp(paths[i], face(i, sizes[i][0], sizes[i][1]), error)) << error;
    }
    return paths;
}

std::array<std::array<int, 2>, 6> allSquare(int n) {
    std::array<std::array<int, 2>, 6> s;
    s.fill({n, n});
    return s;
}

void add32(Bytes& b, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(std::uint8_t(v >> (8 * i)));
}

}  // namespace

TEST(CubeMap, LoadsSixFacesInOrder) {
    TempDir dir;
    const auto paths = writeFaces(dir, allSquare(8));
    std::array<Image, 6> faces;
    std::string error;
    ASSERT_TRUE(loadCubeMap(paths, faces, error)) << error;
    for (int i = 0; i < 6; ++i) {
        SCOPED_TRACE(kCubeFaceNames[i]);
        ASSERT_EQ(faces[i].type, Image::Type::U8);
        ASSERT_EQ(faces[i].width, 8);
        ASSERT_EQ(faces[i].height, 8);
        const std::uint8_t* t = &faces[i].u8[4 * 9];  // an ordinary texel
        EXPECT_EQ(t[0], 40 * i + 10);
        EXPECT_EQ(t[1], 200 - 30 * i);
        EXPECT_EQ(t[2], 7 * i);
        EXPECT_EQ(faces[i].u8[0], 255);  // the white texel stays at the top left
        EXPECT_EQ(faces[i].u8[1], 255);
        EXPECT_NE(faces[i].u8[(8 * 7) * 4 + 1], 255);  // bottom left is not white
    }
}

TEST(CubeMap, FaceNames) {
    EXPECT_STREQ(kCubeFaceNames[0], "+x");
    EXPECT_STREQ(kCubeFaceNames[3], "-y");
    EXPECT_STREQ(kCubeFaceNames[5], "-z");
}

TEST(CubeMap, RefusesNonSquareFace) {
    TempDir dir;
    auto sizes = allSquare(16);
    sizes[3] = {16, 8};
    const auto paths = writeFaces(dir, sizes);
    std::array<Image, 6> faces;
    faces[0] = Image::rgba8(1, 1);  // untouched on failure
    std::string error;
    EXPECT_FALSE(loadCubeMap(paths, faces, error));
    EXPECT_EQ(error, "cube map face -y (" + paths[3] + ") is 16x8; faces must be square");
    EXPECT_EQ(faces[0].width, 1);
    EXPECT_TRUE(faces[1].empty());
}

TEST(CubeMap, RefusesFirstFaceNotSquare) {
    TempDir dir;
    auto sizes = allSquare(4);
    sizes[0] = {4, 5};
    const auto paths = writeFaces(dir, sizes);
    std::array<Image, 6> faces;
    std::string error;
    EXPECT_FALSE(loadCubeMap(paths, faces, error));
    EXPECT_EQ(error, "cube map face +x (" + paths[0] + ") is 4x5; faces must be square");
}

TEST(CubeMap, RefusesFacesOfDifferentSizes) {
    TempDir dir;
    auto sizes = allSquare(16);
    sizes[4] = {32, 32};
    const auto paths = writeFaces(dir, sizes);
    std::array<Image, 6> faces;
    std::string error;
    EXPECT_FALSE(loadCubeMap(paths, faces, error));
    EXPECT_EQ(error, "cube map face +z (" + paths[4] + ") is 32x32, but face +x is 16x16; all faces must be the same size");
    for (const Image& f : faces) EXPECT_TRUE(f.empty());
}

TEST(CubeMap, MissingOrBrokenFaceIsNamed) {
    TempDir dir;
    auto paths = writeFaces(dir, allSquare(4));
    paths[5] = dir / "nowhere.bmp";
    std::array<Image, 6> faces;
    std::string error;
    EXPECT_FALSE(loadCubeMap(paths, faces, error));
    EXPECT_EQ(error, "cube map face -z: cannot open " + paths[5]);

    paths = writeFaces(dir, allSquare(4));
    writeBytes(paths[2], {'B', 'M', 1, 2, 3});
    EXPECT_FALSE(loadCubeMap(paths, faces, error));
    EXPECT_EQ(error.rfind("cube map face +y: " + paths[2] + ": ", 0), 0u) << error;
}

TEST(CubeMap, FacesMayMixFormats) {
    TempDir dir;
    auto paths = writeFaces(dir, allSquare(4));
    paths[1] = dir / "negx.png";
    std::string error;
    ASSERT_TRUE(writePng(paths[1], face(1, 4, 4), error)) << error;
    std::array<Image, 6> faces;
    ASSERT_TRUE(loadCubeMap(paths, faces, error)) << error;
    EXPECT_EQ(faces[1].u8, face(1, 4, 4).u8);
}

TEST(Volume, LoadsBytesAndFloatsFromDisk) {
    TempDir dir;
    Bytes file;
    add32(file, 3);
    add32(file, 2);
    add32(file, 2);
    for (int i = 0; i < 3 * 2 * 2 * 4; ++i) file.push_back(std::uint8_t(5 * i + 1));
    writeBytes(dir / "v.tex", file);
    Volume v;
    std::string error;
    ASSERT_TRUE(loadVolume(dir / "v.tex", v, error)) << error;
    EXPECT_EQ(v.width, 3);
    EXPECT_EQ(v.height, 2);
    EXPECT_EQ(v.depth, 2);
    EXPECT_EQ(v.type, Image::Type::U8);
    EXPECT_EQ(v.u8, Bytes(file.begin() + 12, file.end()));  // kept in file (OpenGL) order

    Bytes ffile;
    add32(ffile, 1);
    add32(ffile, 1);
    add32(ffile, 2);
    const std::vector<float> values = {0.25f, -3.0f, 1e6f, 1.0f, 0.5f, 0.0f, 2.0f, -0.125f};
    for (float f : values) add32(ffile, std::bit_cast<std::uint32_t>(f));
    writeBytes(dir / "f.tex", ffile);
    ASSERT_TRUE(loadVolume(dir / "f.tex", v, error)) << error;
    EXPECT_EQ(v.type, Image::Type::F32);
    EXPECT_EQ(v.depth, 2);
    EXPECT_EQ(v.f32, values);
    EXPECT_TRUE(v.u8.empty());
}

TEST(Volume, WrongSizeAndMissingFile) {
    TempDir dir;
    Bytes file;
    add32(file, 2);
    add32(file, 2);
    add32(file, 2);
    file.resize(12 + 2 * 2 * 2 * 4 - 1);
    writeBytes(dir / "short.tex", file);
    Volume v;
    v.width = 9;  // untouched on failure
    std::string error;
    EXPECT_FALSE(loadVolume(dir / "short.tex", v, error));
    EXPECT_EQ(error, dir / "short.tex" + ": .tex file is 43 bytes; a 2x2x2 texture needs 44 (RGBA bytes) or 140 (RGBA float32)");
    EXPECT_EQ(v.width, 9);

    writeBytes(dir / "tiny.tex", {1, 0, 0, 0, 1, 0});
    EXPECT_FALSE(loadVolume(dir / "tiny.tex", v, error));
    EXPECT_EQ(error, dir / "tiny.tex" + ": truncated .tex: needs 12 bytes of sizes, file has 6");

    EXPECT_FALSE(loadVolume(dir / "absent.tex", v, error));
    EXPECT_EQ(error, "cannot open " + dir / "absent.tex");
    EXPECT_EQ(v.width, 9);
}
