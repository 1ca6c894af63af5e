// The viewer's real window, read back from the X screen it is on: the other
// viewer tests read the offscreen picture (`save`), which a window that shows
// nothing would still pass. Here the screen must show what `glimmer render`
// draws, and the panel beside or over it.
//
// Nothing assumes where the window, the picture or the panel is: the
// picture is searched for on the whole screen (at 1:1, the size it was
// rendered at), and the panel is whatever differs strongly from it.
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "image/image.h"
#include "viewer_process.h"
#include "x_screen.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;
using glimmer::Image;

namespace {

constexpr int kTolerance = 3;   // 8-bit steps: the same llvmpipe draws both
constexpr int kStrong = 48;     // a difference no rounding makes: something else is drawn there

int maxStep(const std::uint8_t* a, const std::uint8_t* b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}
const std::uint8_t* at(const Image& img, int x, int y) { return &img.u8[(size_t(y) * img.width + x) * 4]; }

struct Rect {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive; empty when x1 < x0
    bool empty() const { return x1 < x0 || y1 < y0; }
    int width() const { return empty() ? 0 : x1 - x0 + 1; }
    int height() const { return empty() ? 0 : y1 - y0 + 1; }
    bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    void add(int x, int y) {
        if (empty()) {
            x0 = x1 = x;
            y0 = y1 = y;
        } else {
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    }
};

// Where on the screen the picture is: the rightmost quarter of its columns
// (which a panel at the left or beside it leaves alone) must all match
// within the tolerance; of the places where they do, the one where most of
// the whole picture matches. False when no place matches.
bool findPicture(const Image& screen, const Image& picture, int& px, int& py) {
    int strip = std::max(8, picture.width / 4);
    long best = -1;
    for (int y = 0; y + picture.height <= screen.height; ++y)
        for (int x = 0; x + picture.width <= screen.width; ++x) {
            bool ok = true;
            // A sparse look first, so that most places are rejected at once.
            for (int step : {61, 1})
                for (int j = 0; ok && j < picture.height; j += step)
                    for (int i = picture.width - strip; ok && i < picture.width; i += step)
                        ok = maxStep(at(screen, x + i, y + j), at(picture, i, j)) <= kTolerance;
            if (!ok) continue;
            long matching = 0;
            for (int j = 0; j < picture.height; ++j)
                for (int i = 0; i < picture.width; ++i)
                    matching += maxStep(at(screen, x + i, y + j), at(picture, i, j)) <= kTolerance;
            if (matching > best) best = matching, px = x, py = y;
        }
    return best >= 0;
}

// One look at the screen: empty when it shows the picture (everywhere but
// under the panel) and a panel; else what is wrong.
std::string checkScreen(const Image& screen, const Image& picture) {
    int px = 0, py = 0;
    if (!findPicture(screen, picture, px, py))
        return fmt::format("the {}x{} picture is nowhere on the screen (not even its right quarter)", picture.width,
                           picture.height);
    Rect where{px, py, px + picture.width - 1, py + picture.height - 1};
    // The panel: pixels over the picture that differ strongly from it, and
    // sharp edges (text, frames) off the picture, where the screen and the
    // window's clear colour are flat. Counted in 16x16 cells; the panel is
    // the biggest group of touching cells, so that a wrong pixel elsewhere
    // is not taken for part of it.
    constexpr int kCell = 16;
    int cw = (screen.width + kCell - 1) / kCell, ch = (screen.height + kCell - 1) / kCell;
    std::vector<Rect> cells(size_t(cw) * ch);
    std::vector<long> counts(cells.size(), 0);
    for (int y = 0; y < screen.height; ++y)
        for (int x = 0; x < screen.width; ++x) {
            bool strong;
            if (where.contains(x, y))
                strong = maxStep(at(screen, x, y), at(picture, x - px, y - py)) > kStrong;
            else
                strong = x + 1 < screen.width && !where.contains(x + 1, y) &&
                         maxStep(at(screen, x, y), at(screen, x + 1, y)) > kStrong;
            if (!strong) continue;
            size_t c = size_t(y / kCell) * cw + x / kCell;
            cells[c].add(x, y);
            ++counts[c];
        }
    Rect panel;
    long panelPixels = 0;
    std::vector<int> group(cells.size(), -1);
    for (size_t start = 0; start < cells.size(); ++start) {
        if (!counts[start] || group[start] >= 0) continue;
        Rect box;
        long pixels = 0;
        std::vector<size_t> todo = {start};
        group[start] = int(start);
        while (!todo.empty()) {
            size_t c = todo.back();
            todo.pop_back();
            box.add(cells[c].x0, cells[c].y0);
            box.add(cells[c].x1, cells[c].y1);
            pixels += counts[c];
            int cx = int(c % cw), cy = int(c / cw);
            for (int ny = std::max(0, cy - 1); ny <= std::min(ch - 1, cy + 1); ++ny)
                for (int nx = std::max(0, cx - 1); nx <= std::min(cw - 1, cx + 1); ++nx) {
                    size_t n = size_t(ny) * cw + nx;
                    if (counts[n] && group[n] < 0) group[n] = int(start), todo.push_back(n);
                }
        }
        if (pixels > panelPixels) panelPixels = pixels, panel = box;
    }
    if (panelPixels < 500 || panel.width() < 100 || panel.height() < 40)
        return fmt::format("no panel: {} pixels differ strongly from the picture at ({}, {}), in a {}x{} box",
                           panelPixels, px, py, panel.width(), panel.height());
    // Everywhere the panel is not, the picture, pixel for pixel.
    Rect covered{panel.x0 - 2, panel.y0 - 2, panel.x1 + 2, panel.y1 + 2};
    long wrong = 0;
    int wx = 0, wy = 0, worst = 0;
    for (int j = 0; j < picture.height; ++j)
        for (int i = 0; i < picture.width; ++i) {
            if (covered.contains(px + i, py + j)) continue;
            int d = maxStep(at(screen, px + i, py + j), at(picture, i, j));
            if (d > kTolerance) ++wrong;
            if (d > worst) worst = d, wx = i, wy = j;
        }
    if (wrong > 0)
        return fmt::format("the picture at ({}, {}) is wrong in {} pixels outside the panel ({}, {})-({}, {}); "
                           "worst {} steps at ({}, {}) of the picture",
                           px, py, wrong, panel.x0, panel.y0, panel.x1, panel.y1, worst, wx, wy);
    return {};
}

TEST(Window, ShowsWhatRenderDrawsAndThePanel) {
    fs::path dir = fs::temp_directory_path() / ("glimmer_window_test_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    struct Cleanup {
        fs::path p;
        ~Cleanup() { fs::remove_all(p); }
    } cleanup{dir};
    fs::path src(GLIMMER_SOURCE_DIR);
    fs::copy_file(src / "scripts/bloom.glib", dir / "bloom.glib");
    for (auto f : {"superblur.vert", "superblur.frag", "bloom.vert", "bloom.frag"})
        fs::copy_file(src / "shaders" / f, dir / f);
    fs::copy_file(src / "textures/grid.bmp", dir / "grid.bmp");

    // The reference: `glimmer render` of the same script, size and values.
    const std::string size = "640x480";
    std::string cmd = std::string(GLIMMER_BIN) + " render " + (dir / "bloom.glib").string() + " --size " + size +
                      " --set uHalfSize=5 --set uAdd=3 -o " + (dir / "render.png").string() + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    Image picture;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage((dir / "render.png").string(), picture, why)) << why;
    ASSERT_EQ(picture.type, Image::Type::U8);

    VirtualScreen screen(1024, 768);
    ASSERT_FALSE(screen.display().empty()) << screen.why();
    ViewerProcess v({"bloom.glib", "--size", size, "--set", "uHalfSize=5", "--set", "uAdd=3"}, dir,
                    screen.display());
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();

    // The first frames may not be on the screen yet, nor the panel at its
    // final size: look again until the screen is right, for a while.
    std::string wrong = "no capture";
    Image shot;
    auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < end) {
        if (!screen.capture(shot, why)) {
            wrong = why;
            break;
        }
        wrong = checkScreen(shot, picture);
        if (wrong.empty()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    if (!wrong.empty() && !shot.empty()) {
        // Kept for whoever reads the failure.
        fs::path keep = fs::temp_directory_path() / ("glimmer_window_test_" + std::to_string(::getpid()) + ".png");
        if (glimmer::writePng(keep.string(), shot, why)) wrong += "; the screen is in " + keep.string();
    }
    EXPECT_EQ(wrong, "") << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// The search on made-up screens, so that it is known to find the picture
// wherever a layout puts it, and to say no when it is not shown right.
Image noise(int w, int h) {
    Image img = Image::rgba8(w, h);
    std::uint32_t state = 12345;
    for (size_t i = 0; i < img.u8.size(); ++i) {
        state = state * 1664525u + 1013904223u;
        img.u8[i] = i % 4 == 3 ? 255 : std::uint8_t(state >> 24);
    }
    return img;
}

void fill(Image& img, int x0, int y0, int x1, int y1, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            std::uint8_t* p = &img.u8[(size_t(y) * img.width + x) * 4];
            p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
        }
}

void paste(Image& screen, const Image& picture, int px, int py) {
    for (int y = 0; y < picture.height; ++y)
        std::copy_n(&picture.u8[size_t(y) * picture.width * 4], picture.width * 4,
                    &screen.u8[(size_t(py + y) * screen.width + px) * 4]);
}

// A panel: a dark box with light "text" in it.
void drawPanel(Image& screen, int x0, int y0, int x1, int y1) {
    fill(screen, x0, y0, x1, y1, 15, 15, 18);
    for (int y = y0 + 6; y < y1 - 6; y += 12)
        for (int x = x0 + 4; x < x1 - 4; x += 4) fill(screen, x, y, x + 2, y + 7, 220, 220, 220);
}

TEST(Window, FindsThePictureWhereverTheLayoutPutsIt) {
    Image picture = noise(200, 120);
    // The panel over the picture's left part, the window at the screen's
    // corner (the layout of today).
    Image over = Image::rgba8(400, 260);
    fill(over, 0, 0, 400, 260, 0, 0, 0);
    paste(over, picture, 0, 0);
    drawPanel(over, 4, 4, 110, 80);
    EXPECT_EQ(checkScreen(over, picture), "");
    // The panel docked beside the picture, the window elsewhere on the screen.
    Image beside = Image::rgba8(400, 260);
    fill(beside, 0, 0, 400, 260, 0, 0, 0);
    fill(beside, 20, 30, 390, 200, 31, 31, 36);
    paste(beside, picture, 180, 50);
    drawPanel(beside, 24, 34, 170, 190);
    EXPECT_EQ(checkScreen(beside, picture), "");

    // Not shown: only the panel.
    Image nothing = Image::rgba8(400, 260);
    fill(nothing, 0, 0, 400, 260, 31, 31, 36);
    drawPanel(nothing, 4, 4, 110, 80);
    EXPECT_NE(checkScreen(nothing, picture).find("nowhere on the screen"), std::string::npos);
    // No panel.
    Image bare = beside;
    fill(bare, 20, 30, 180, 200, 31, 31, 36);
    EXPECT_NE(checkScreen(bare, picture).find("no panel"), std::string::npos) << checkScreen(bare, picture);
    // One pixel wrong, away from the panel and from the quarter the search looks at.
    Image spot = over;
    spot.u8[(size_t(100) * spot.width + 130) * 4] ^= 0x40;
    EXPECT_NE(checkScreen(spot, picture).find("wrong in 1 pixels"), std::string::npos) << checkScreen(spot, picture);
}

}  // namespace
