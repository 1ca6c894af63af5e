// The viewer's controls, each driven as a person would (xdotool keys,
// clicks and drags on the virtual X server) or through the command lines a
// test can send, and each judged by what it leaves behind: pixels read back
// from the window, files saved, lines on stderr, the X clipboard, the exit
// status.
//
// Most use a script of three constant colours: a float target (unit 3,
// RGBA32F) holding (2, 0.5, 0.25, 1), an 8-bit target (unit 4) holding
// green, and a blue screen, so every pixel on screen says where it came from.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <thread>

#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "image/image.h"
#include "viewer_process.h"
#include "x11_driver.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

namespace {

struct Rgb {
    int r, g, b;
};
constexpr Rgb kHot = {255, 128, 64};   // (2, 0.5, 0.25) clamped to 8 bits, as a window shows it
constexpr Rgb kGreen = {0, 204, 51};   // (0, 0.8, 0.2)
constexpr Rgb kBlue = {51, 102, 255};  // (0.2, 0.4, 1)
constexpr int kPicture = 128;          // the picture's size (--size 128x128)

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::trunc) << text; }

std::string flatFrag(const char* colour) {
    return std::string("#version 330 compatibility\n\nvoid main( )\n{\n    gl_FragColor = vec4( ") + colour + " );\n}\n";
}

struct Project {
    glimmer::testing::TestFolder folder{"glimmer_controls_test_"};
    fs::path dir = folder.path;
    Project() {
        fs::path src(GLIMMER_SOURCE_DIR);
        fs::copy_file(src / "shaders/bloom.vert", dir / "flat.vert");
        write(dir / "hot.frag", flatFrag("2., 0.5, 0.25, 1."));
        write(dir / "green.frag", flatFrag("0., 0.8, 0.2, 1."));
        write(dir / "blue.frag", flatFrag("0.2, 0.4, 1., 1."));
        write(dir / "targets.glib",
              "##OpenGL GLIB\n"
              "Ortho -1 1 -1 1\n"
              "LookAt 0 0 1  0 0 0  0 1 0\n"
              "Texture2D 3 64 64 RGBA32F\n"
              "RenderToTexture 3\n"
              "Clear\n"
              "Vertex flat.vert\n"
              "Fragment hot.frag\n"
              "Program Hot\n"
              "QuadXY 0 1\n"
              "Texture2D 4 64 64\n"
              "RenderToTexture 4\n"
              "Clear\n"
              "Vertex flat.vert\n"
              "Fragment green.frag\n"
              "Program Green\n"
              "QuadXY 0 1\n"
              "RenderToTexture\n"
              "Clear\n"
              "Vertex flat.vert\n"
              "Fragment blue.frag\n"
              "Program Blue\n"
              "QuadXY 0 1\n");
    }
};

const std::uint8_t* at(const glimmer::Image& img, int x, int y) { return &img.u8[(size_t(y) * img.width + x) * 4]; }

bool near(const std::uint8_t* p, Rgb c, int tolerance = 2) {
    return std::abs(p[0] - c.r) <= tolerance && std::abs(p[1] - c.g) <= tolerance && std::abs(p[2] - c.b) <= tolerance;
}

// Whether every pixel of the rectangle [x0, x1) x [y0, y1) is `c`.
bool allAre(const glimmer::Image& img, int x0, int y0, int x1, int y1, Rgb c) {
    if (img.empty() || x1 > img.width || y1 > img.height) return false;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            if (!near(at(img, x, y), c)) return false;
    return true;
}

// Calls `check` until it says yes or `timeout` passes.
bool eventually(const std::function<bool()>& check, std::chrono::milliseconds timeout = 5000ms) {
    auto end = Clock::now() + timeout;
    do {
        if (check()) return true;
        std::this_thread::sleep_for(50ms);
    } while (Clock::now() < end);
    return check();
}

// Waits until the window is wider than `minW` and keeps its size for 300 ms.
bool stableWindow(const XViewer& x, int minW) {
    int lastW = -1, lastH = -1;
    auto stableSince = Clock::now();
    return eventually(
        [&] {
            int w = 0, h = 0;
            if (!windowSize(x, w, h)) return false;
            if (w != lastW || h != lastH) {
                lastW = w, lastH = h;
                stableSince = Clock::now();
                return false;
            }
            return w > minW && Clock::now() - stableSince >= 300ms;
        },
        10000ms);
}

// The viewer's window once the panel has settled beside the picture.
std::optional<XViewer> settled(ViewerProcess& v, const fs::path& dir, int pictureW = kPicture) {
    if (!v.waitForLog("glimmer view: ui scale")) return std::nullopt;
    auto x = findViewer(dir);
    if (!x || !stableWindow(*x, pictureW + 200)) return std::nullopt;
    return x;
}

int count(const std::string& text, const std::string& needle) {
    int n = 0;
    for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
    return n;
}

std::string move(const XViewer& x, int px, int py) {
    return "mousemove --window " + x.window + " " + std::to_string(px) + " " + std::to_string(py);
}

// Connected groups of pixels of colour `c` (4-neighbours) inside the
// rectangle from x0 on, each as its bounding box (x0, y0, x1, y1 inclusive)
// and pixel count; only groups of at least `minPixels`.
struct Blob {
    int x0, y0, x1, y1;
    long pixels;
};
std::vector<Blob> blobs(const glimmer::Image& img, int fromX, Rgb c, long minPixels) {
    std::vector<Blob> out;
    std::vector<char> seen(size_t(img.width) * img.height, 0);
    for (int y = 0; y < img.height; ++y)
        for (int x = fromX; x < img.width; ++x) {
            if (seen[size_t(y) * img.width + x] || !near(at(img, x, y), c)) continue;
            Blob b{x, y, x, y, 0};
            std::vector<std::pair<int, int>> stack{{x, y}};
            seen[size_t(y) * img.width + x] = 1;
            while (!stack.empty()) {
                auto [px, py] = stack.back();
                stack.pop_back();
                ++b.pixels;
                b.x0 = std::min(b.x0, px), b.x1 = std::max(b.x1, px), b.y0 = std::min(b.y0, py), b.y1 = std::max(b.y1, py);
                for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    int nx = px + dx, ny = py + dy;
                    if (nx < fromX || ny < 0 || nx >= img.width || ny >= img.height) continue;
                    if (seen[size_t(ny) * img.width + nx] || !near(at(img, nx, ny), c)) continue;
                    seen[size_t(ny) * img.width + nx] = 1;
                    stack.push_back({nx, ny});
                }
            }
            if (b.pixels >= minPixels) out.push_back(b);
        }
    return out;
}

glimmer::Image load(const fs::path& p) {
    glimmer::Image img;
    std::string why;
    glimmer::loadImage(p.string(), img, why);
    return img;
}

// Saves under `name`, waits for the file, returns its bytes.
std::vector<unsigned char> saved(ViewerProcess& v, const fs::path& dir, const std::string& name) {
    v.send("save " + name);
    if (!waitForFile(dir / name, 10s)) return {};
    return readBytes(dir / name);
}

// 1. An error's line in the panel, clicked, puts its file:line on the X
// clipboard (and says so on stderr).
TEST(ViewerControls, ClickingAnErrorCopiesItsFileAndLine) {
    Project p;
    ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    write(p.dir / "green.frag", "#version 330 compatibility\n\nvoid main( )\n{\n    gl_FragColor = undefinedThing;\n}\n");
    ASSERT_TRUE(v.waitForLog("failed; keeping the last good picture")) << v.log();
    ASSERT_TRUE(stableWindow(*x, kPicture + 200));  // the panel grows to hold the message
    // The error is drawn in its own colour, (1, 0.55, 0.5): find its text
    // in the panel and click on it.
    constexpr Rgb kErrorText = {255, 140, 128};
    std::vector<Blob> text;
    ASSERT_TRUE(eventually([&] {
        text = blobs(captureWindow(*x, p.dir), kPicture, kErrorText, 3);
        return !text.empty();
    })) << v.log();
    const Blob& b = text.front();
    xdotool(*x, move(*x, (b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2) + " sleep 0.2 click 1");
    ASSERT_TRUE(v.waitForLog("glimmer view: copied ")) << v.log();
    std::string log = v.log();
    size_t from = log.find("glimmer view: copied ") + 21;
    std::string where = log.substr(from, log.find('\n', from) - from);
    EXPECT_NE(where.find("green.frag:5"), std::string::npos) << where;
    // What another program pastes (Tk reads the CLIPBOARD selection, which
    // the viewer owns and answers while it waits for events).
    if (std::system("python3 -c 'import tkinter' 2>/dev/null") != 0) GTEST_SKIP() << "no python3-tk to read the clipboard";
    std::string clip = shellOutput(x->env +
                          " timeout 10 python3 -c 'import tkinter; r = tkinter.Tk(); r.withdraw(); "
                          "print(r.clipboard_get(), end=\"\")' 2>&1");
    EXPECT_EQ(clip, where);
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 2. Space pauses the Timer (the picture stops changing) and plays it again.
TEST(ViewerControls, SpacePausesAndPlaysTheTimer) {
    Project p;
    fs::path src(GLIMMER_SOURCE_DIR);
    fs::copy_file(src / "scripts/orbit.glib", p.dir / "orbit.glib");
    fs::copy_file(src / "shaders/orbit.frag", p.dir / "orbit.frag");
    fs::copy_file(src / "shaders/bloom.vert", p.dir / "bloom.vert");
    ViewerProcess v({"orbit.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    int n = 0;
    // Two saves 200 ms apart: the dot moves 1/20 of its circle between them
    // while the Timer runs, not at all while it is paused.
    auto changing = [&] {
        std::string a = "t" + std::to_string(n++) + ".png", b = "t" + std::to_string(n++) + ".png";
        auto first = saved(v, p.dir, a);
        std::this_thread::sleep_for(200ms);
        auto second = saved(v, p.dir, b);
        return !first.empty() && !second.empty() && first != second;
    };
    EXPECT_TRUE(changing()) << v.log();
    xdotool(*x, move(*x, 64, 64) + " key space");
    EXPECT_TRUE(eventually([&] { return !changing(); })) << "still changing after space\n" << v.log();
    EXPECT_FALSE(changing()) << "paused, yet changing\n" << v.log();
    xdotool(*x, move(*x, 64, 64) + " key space");
    EXPECT_TRUE(eventually([&] { return changing(); })) << "not changing after the second space\n" << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 2. F fills the screen (xvfb-run's 1024x768) and F again gives the window
// its size back.
TEST(ViewerControls, FTogglesFullscreen) {
    Project p;
    ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    int w0 = 0, h0 = 0, w = 0, h = 0;
    ASSERT_TRUE(windowSize(*x, w0, h0));
    xdotool(*x, move(*x, 64, 64) + " key f");
    EXPECT_TRUE(eventually([&] { return windowSize(*x, w, h) && w == 1024 && h == 768; }))
        << w << "x" << h << "\n" << v.log();
    // The picture fills what the panel leaves: blue at the screen's left edge, far below 128.
    EXPECT_TRUE(eventually([&] { return allAre(captureWindow(*x, p.dir), 0, 300, 16, 316, kBlue); })) << v.log();
    xdotool(*x, move(*x, 64, 64) + " key f");
    EXPECT_TRUE(eventually([&] { return windowSize(*x, w, h) && w == w0 && h == h0; }))
        << w << "x" << h << " not " << w0 << "x" << h0 << "\n" << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 2. R loads the script again, from disk.
TEST(ViewerControls, RReloads) {
    Project p;
    ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    xdotool(*x, move(*x, 64, 64) + " key r");
    EXPECT_TRUE(v.waitForLog("glimmer view: reloaded\n", 1, 5s)) << v.log();
    xdotool(*x, move(*x, 64, 64) + " key r");
    EXPECT_TRUE(v.waitForLog("glimmer view: reloaded\n", 2, 5s)) << v.log();
    EXPECT_TRUE(allAre(captureWindow(*x, p.dir), 0, 0, kPicture, kPicture, kBlue)) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 2. Q and Esc each close the window, and the viewer exits 0.
TEST(ViewerControls, QAndEscQuitWithStatusZero) {
    Project p;
    for (const char* key : {"q", "Escape"}) {
        ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
        auto x = settled(v, p.dir);
        ASSERT_TRUE(x) << v.log();
        xdotool(*x, move(*x, 64, 64) + " key " + key);
        EXPECT_EQ(v.waitExit(5s), 0) << key << "\n" << v.log();
    }
}

// 3. "Show values" draws the same box and text at the same place in the
// window as in a saved PNG, pixel for pixel (bar one step of rounding where
// the window blends the dark box).
TEST(ViewerControls, ShowValuesOverlayIsTheSameOnScreenAndInTheSavedPng) {
    Project p;
    fs::path src(GLIMMER_SOURCE_DIR);
    fs::copy_file(src / "scripts/bloom.glib", p.dir / "bloom.glib");
    for (auto f : {"superblur.vert", "superblur.frag", "bloom.vert", "bloom.frag"})
        fs::copy_file(src / "shaders" / f, p.dir / f);
    fs::copy_file(src / "textures/grid.bmp", p.dir / "grid.bmp");
    ViewerProcess v({"bloom.glib", "--size", "256x256", "--set", "uAdd=1.5"}, p.dir);
    auto x = settled(v, p.dir, 256);
    ASSERT_TRUE(x) << v.log();
    ASSERT_FALSE(saved(v, p.dir, "plain.png").empty()) << v.log();
    v.send("values on");
    ASSERT_FALSE(saved(v, p.dir, "values.png").empty()) << v.log();
    glimmer::Image plain = load(p.dir / "plain.png"), values = load(p.dir / "values.png");
    ASSERT_EQ(values.width, 256);
    // The overlay in the PNG: where it differs from the plain picture.
    int x0 = 256, y0 = 256, x1 = -1, y1 = -1;
    for (int y = 0; y < 256; ++y)
        for (int i = 0; i < 256; ++i)
            if (!near(at(plain, i, y), {at(values, i, y)[0], at(values, i, y)[1], at(values, i, y)[2]}, 0))
                x0 = std::min(x0, i), y0 = std::min(y0, y), x1 = std::max(x1, i), y1 = std::max(y1, y);
    ASSERT_GE(x1, x0) << "no overlay in the saved PNG";
    EXPECT_EQ(x0, 8);
    EXPECT_EQ(y0, 8);
    int worst = 256;
    EXPECT_TRUE(eventually([&] {
        glimmer::Image shot = captureWindow(*x, p.dir);
        if (shot.width < 256 || shot.height < 256) return false;
        worst = 0;
        for (int y = 0; y < 256; ++y)  // the whole picture, the overlay and around it
            for (int i = 0; i < 256; ++i)
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(at(shot, i, y)[c] - at(values, i, y)[c]));
        return worst <= 1;
    })) << "the window's picture differs from the saved PNG by " << worst << " steps (overlay at " << x0 << "," << y0
        << " to " << x1 << "," << y1 << ")";
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 4. The probe, over a float target, reads the float values there (2 is
// past what 8 bits show), and over the screen its 8-bit values.
TEST(ViewerControls, ProbeShowsTheFloatValuesUnderThePointer) {
    Project p;
    ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    v.send("probe");
    ASSERT_TRUE(v.waitForLog("glimmer view: probe: off")) << v.log();
    v.send("show 3");
    v.send("probe on");
    // The pointer over the picture (a little to and fro, so that the window
    // sees it move), then `probe` prints the reading of the last frame.
    int wiggle = 0;
    auto reads = [&](const std::string& want) {
        return eventually([&] {
            xdotool(*x, move(*x, 40 + (wiggle++ % 2), 50));
            std::string before = v.log();
            v.send("probe");
            if (!v.waitForLog("glimmer view: probe", count(before, "glimmer view: probe") + 1, 2s)) return false;
            eventually([&] { return v.log().find('\n', before.size()) != std::string::npos; }, 1000ms);
            std::string line = v.log().substr(before.size());
            return line.find(want) != std::string::npos;
        });
    };
    EXPECT_TRUE(reads(": r 2  g 0.5  b 0.25  a 1\n")) << v.log();
    v.send("show screen");
    EXPECT_TRUE(reads("of screen: r 0.2  g 0.4  b 1  a 1\n")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 5. The before/after split: unit 4 left of the divider, the screen right
// of it, and a drag across the picture moves the divider.
TEST(ViewerControls, SplitShowsOneTargetEachSideOfTheDraggedDivider) {
    Project p;
    ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    v.send("split 4 screen");
    // At the start the divider is half way.
    EXPECT_TRUE(eventually([&] {
        auto shot = captureWindow(*x, p.dir);
        return allAre(shot, 0, 0, 60, kPicture, kGreen) && allAre(shot, 68, 0, kPicture, kPicture, kBlue);
    })) << v.log();
    xdotool(*x, move(*x, 64, 64) + " sleep 0.2 mousedown 1 sleep 0.2 " + move(*x, 80, 70) + " sleep 0.2 " + move(*x, 100, 70) +
                    " sleep 0.2 mouseup 1");
    EXPECT_TRUE(eventually([&] {
        auto shot = captureWindow(*x, p.dir);
        return allAre(shot, 0, 0, 96, kPicture, kGreen) && allAre(shot, 104, 0, kPicture, kPicture, kBlue);
    })) << v.log();
    v.send("split off");
    EXPECT_TRUE(eventually([&] { return allAre(captureWindow(*x, p.dir), 0, 0, kPicture, kPicture, kBlue); })) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

// 6. The panel has one thumbnail per render target, and clicking one
// shows that target in place of the picture; clicking it again, the picture.
TEST(ViewerControls, ClickingAThumbnailInspectsThatTarget) {
    Project p;
    ViewerProcess v({"targets.glib", "--size", "128x128"}, p.dir);
    auto x = settled(v, p.dir);
    ASSERT_TRUE(x) << v.log();
    std::vector<Blob> hot, green;
    ASSERT_TRUE(eventually([&] {
        auto shot = captureWindow(*x, p.dir);
        hot = blobs(shot, kPicture, kHot, 200);
        green = blobs(shot, kPicture, kGreen, 200);
        return hot.size() == 1 && green.size() == 1;
    })) << hot.size() << " thumbnails of unit 3, " << green.size() << " of unit 4\n" << v.log();
    auto click = [&](const Blob& b) {
        xdotool(*x, move(*x, (b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2) + " sleep 0.2 click 1 sleep 0.2 " + move(*x, 64, 64));
    };
    click(green.front());
    EXPECT_TRUE(eventually([&] { return allAre(captureWindow(*x, p.dir), 0, 0, kPicture, kPicture, kGreen); })) << v.log();
    click(hot.front());
    EXPECT_TRUE(eventually([&] { return allAre(captureWindow(*x, p.dir), 0, 0, kPicture, kPicture, kHot); })) << v.log();
    // What is saved is the inspected target: unit 3's float values, clamped to 8 bits.
    ASSERT_FALSE(saved(v, p.dir, "inspected.png").empty()) << v.log();
    glimmer::Image img = load(p.dir / "inspected.png");
    ASSERT_FALSE(img.empty());
    EXPECT_TRUE(allAre(img, 0, 0, img.width, img.height, kHot));
    click(hot.front());
    EXPECT_TRUE(eventually([&] { return allAre(captureWindow(*x, p.dir), 0, 0, kPicture, kPicture, kBlue); })) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

}  // namespace
