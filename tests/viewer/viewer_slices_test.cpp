// The viewer draws heavy frames a slice at a time (gl/renderer_sliced.cpp)
// and drops a frame when a slider moves again. Whatever was dropped on the
// way, the picture it ends on is exactly what `render` draws.
#include <sys/wait.h>

#include <cstdlib>
#include <thread>

#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "viewer_process.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;
using namespace std::chrono_literals;

namespace {

// A slider dragged over the seed's superblur: every new value replaces the
// frame under way (1 ms slices here, so each is left part-way through the
// blur), and the last change reaches only the composite. Were the blur's
// unfinished bands not handed on to the next frame, the saved picture would
// composite a blur drawn partly with older values.
TEST(ViewerSlices, ADragOverAHeavyPassEndsOnExactlyTheRenderedPicture) {
    glimmer::testing::TestFolder folder{"glimmer_slices_test_"};
    const fs::path dir = folder.path, src(GLIMMER_SOURCE_DIR);
    fs::copy_file(src / "scripts/bloom.glib", dir / "bloom.glib");
    for (auto f : {"superblur.vert", "superblur.frag", "bloom.vert", "bloom.frag"}) fs::copy_file(src / "shaders" / f, dir / f);
    fs::copy_file(src / "textures/grid.bmp", dir / "grid.bmp");

    ::setenv("GLIMMER_SLICE_MS", "1", 1);
    ViewerProcess v({"bloom.glib", "--size", "256x256"}, dir);
    ::unsetenv("GLIMMER_SLICE_MS");
    ASSERT_TRUE(v.waitForLog("glimmer view: ui scale")) << v.log();
    for (int half : {3, 7, 11, 5, 9}) {
        v.send("set uHalfSize " + std::to_string(half));
        std::this_thread::sleep_for(40ms);
    }
    v.send("set uAdd 2");
    std::this_thread::sleep_for(40ms);
    v.send("save view.png");
    ASSERT_TRUE(waitForFile(dir / "view.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();

    const std::string cmd = std::string(GLIMMER_BIN) + " render " + (dir / "bloom.glib").string() +
                            " --size 256x256 --set uHalfSize=9 --set uAdd=2 -o " + (dir / "render.png").string() +
                            " 2>/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_EQ(readBytes(dir / "view.png"), readBytes(dir / "render.png"));
}

}  // namespace
