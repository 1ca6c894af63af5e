// The viewer in a real window: what it saves is what `glimmer render` draws,
// and a broken edit costs neither the picture nor the slider values.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include <gtest/gtest.h>

#include "common/calibration_scene.h"
#include "common/test_folder.h"
#include "seed_project.h"
#include "viewer_process.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;

namespace {

struct Project : SeedProject {
    Project() : SeedProject("glimmer_viewer_test_") {}
};

int renderPng(const fs::path& script, const std::vector<std::string>& sets, const fs::path& out) {
    std::string cmd = std::string(GLIMMER_BIN) + " render " + script.string() + " --size 256x256 -o " + out.string();
    for (const auto& s : sets) cmd += " --set " + s;
    cmd += " 2>/dev/null";
    int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The viewer's saved `file` is byte for byte what `glimmer render` writes at
// these --set values.
void expectSavedIsRendered(const Project& p, const std::string& file, const std::vector<std::string>& sets) {
    ASSERT_EQ(renderPng(p.dir / "bloom.glib", sets, p.dir / "render.png"), 0);
    EXPECT_EQ(readBytes(p.dir / file), readBytes(p.dir / "render.png"));
}

TEST(Viewer, SavedPictureIsWhatRenderDraws) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "256x256"}, p.dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();
    v.send("set uHalfSize 5");
    v.send("set uAdd 3");
    v.send("save view.png");
    ASSERT_TRUE(waitForFile(p.dir / "view.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    expectSavedIsRendered(p, "view.png", {"uHalfSize=5", "uAdd=3"});
}

TEST(Viewer, BrokenEditKeepsPictureAndSlidersThenRecovers) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "256x256"}, p.dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();
    v.send("set uHalfSize 5");
    v.send("set uAdd 3");
    v.send("save before.png");
    ASSERT_TRUE(waitForFile(p.dir / "before.png")) << v.log();

    // Break the composite shader on a line we know.
    std::string good;
    {
        std::ifstream f(p.dir / "bloom.frag");
        good.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    std::string broken = good;
    broken.replace(broken.find("vec3 rgbblur"), 12, "vec3 rgbblur = undefinedThing; vec3 unused");
    std::ofstream(p.dir / "bloom.frag", std::ios::trunc) << broken;
    ASSERT_TRUE(v.waitForLog("failed; keeping the last good picture")) << v.log();
    EXPECT_NE(v.log().find("bloom.frag:12:"), std::string::npos) << v.log();

    v.send("save broken.png");
    ASSERT_TRUE(waitForFile(p.dir / "broken.png")) << v.log();
    EXPECT_EQ(readBytes(p.dir / "broken.png"), readBytes(p.dir / "before.png"));

    // Fixed again: the script reloads and the sliders still hold 5 and 3.
    std::ofstream(p.dir / "bloom.frag", std::ios::trunc) << good;
    ASSERT_TRUE(v.waitForLog("reloaded after a change to")) << v.log();
    v.send("save after.png");
    ASSERT_TRUE(waitForFile(p.dir / "after.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    EXPECT_EQ(readBytes(p.dir / "after.png"), readBytes(p.dir / "before.png"));
}

TEST(Viewer, ExecRunsCommandsAndQuits) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "256x256", "--no-stdin", "--exec",
                     "set uHalfSize 5; set uAdd 3; show 6; show screen; save exec.png; quit"},
                    p.dir);
    ASSERT_TRUE(waitForFile(p.dir / "exec.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    expectSavedIsRendered(p, "exec.png", {"uHalfSize=5", "uAdd=3"});
}

// Issue 39: several commands on one line of standard input, as --exec takes
// them (`set uAdd 2; set uHalfSize 11` was refused as one command).
TEST(Viewer, OneStdinLineMayHoldSeveralCommands) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "256x256"}, p.dir);
    v.send("set uHalfSize 5; set uAdd 3; save line.png");
    ASSERT_TRUE(waitForFile(p.dir / "line.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    expectSavedIsRendered(p, "line.png", {"uHalfSize=5", "uAdd=3"});
}

// `save` never writes over one of the script's own files (issue 37: `save
// bloom.frag` turned the shader into a PNG); a name it may use still saves.
TEST(Viewer, SaveRefusesTheScriptsOwnFiles) {
    Project p;
    const auto frag = readBytes(p.dir / "bloom.frag"), glib = readBytes(p.dir / "bloom.glib");
    ViewerProcess v({"bloom.glib", "--size", "64x64", "--no-stdin", "--exec",
                     "save bloom.frag; save ./x1/../bloom.glib; save fine.png; quit"},
                    p.dir);
    ASSERT_TRUE(waitForFile(p.dir / "fine.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    EXPECT_TRUE(v.waitForLog("glimmer view: save bloom.frag: that is 'bloom.frag', which the script reads; write the "
                             "picture under another name")) << v.log();
    EXPECT_TRUE(v.waitForLog("glimmer view: save ./x1/../bloom.glib: that is 'bloom.glib', which the script reads"))
        << v.log();
    EXPECT_EQ(readBytes(p.dir / "bloom.frag"), frag);
    EXPECT_EQ(readBytes(p.dir / "bloom.glib"), glib);
}

// The panel's health badge has a twin on stderr: a float target holding a
// NaN is reported as soon as it is drawn.
TEST(Viewer, ReportsANanInATarget) {
    fs::path data = fs::path(GLIMMER_SOURCE_DIR) / "tests/data/cli";
    ViewerProcess v({"nan.glib", "--size", "64x64", "--no-stdin", "--exec", "save " + (fs::temp_directory_path() /
                     ("glimmer_nan_view_" + std::to_string(::getpid()) + ".png")).string() + "; quit"}, data);
    EXPECT_TRUE(v.waitForLog("health: unit 6 (RGBA16F 16x16): 12 NaN")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    fs::remove(fs::temp_directory_path() / ("glimmer_nan_view_" + std::to_string(::getpid()) + ".png"));
}

// What the viewer saves against the double-precision CPU reference, not
// against `glimmer render` (a bug both share would pass that): the
// calibration scene at uHalfSize 3, uAdd 2 within 1 + uAdd steps.
TEST(Viewer, SavedPictureMatchesTheCpuReference) {
    namespace cal = glimmer::calibration;
    fs::path dir = fs::temp_directory_path() / ("glimmer_viewer_ref_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    struct Cleanup {
        fs::path p;
        ~Cleanup() { fs::remove_all(p); }
    } cleanup{dir};
    std::string why;
    fs::path script = cal::writeScene(dir, why);
    ASSERT_FALSE(script.empty()) << why;
    for (auto f : {"superblur.vert", "superblur.frag", "bloom.vert", "bloom.frag"})
        fs::copy_file(fs::path(cal::shaderDir()) / f, dir / f);
    {
        ViewerProcess v({"calibration.glib", "--no-stdin", "--exec", "set uHalfSize 3; set uAdd 2; save view.png; quit"},
                        dir);
        ASSERT_TRUE(waitForFile(dir / "view.png")) << v.log();
        EXPECT_EQ(v.quit(), 0) << v.log();
    }
    glimmer::Image saved;
    ASSERT_TRUE(glimmer::loadImage((dir / "view.png").string(), saved, why)) << why;
    ASSERT_EQ(saved.width, cal::kW);
    ASSERT_EQ(saved.height, cal::kH);
    std::string where;
    EXPECT_LE(cal::maxStepsIn(saved, 0, 0, cal::expectedScreen(cal::input(dir), 3, 2.0), &where), 3) << where;
}

// `panel`'s picture= is a hash of the whole picture as shown, which a tour
// reads to tell whether a click changed the picture: in a picture four
// times as wide as tall, a change in its right quarter alone changes it,
// and setting the value back gives the first hash again.
TEST(Viewer, ThePanelsPictureHashCoversAllOfAWidePicture) {
    glimmer::testing::TestFolder folder("glimmer_viewer_wide_");
    const fs::path& dir = folder.path;
    // The quad's texture coordinates made its corners: it fills the picture.
    std::ofstream(dir / "fill.vert") << "#version 330 compatibility\n"
                                        "void main() { gl_Position = vec4(gl_MultiTexCoord0.st * 2. - 1., 0., 1.); }\n";
    std::ofstream(dir / "right.frag") << "#version 330 compatibility\nuniform float uR;\n"
                                         "void main() { gl_FragColor = vec4(gl_FragCoord.x > 192. ? uR : 0., .2, 0., 1.); }\n";
    std::ofstream(dir / "wide.glib") << "Vertex fill.vert\nFragment right.frag\nProgram Right uR <0. 0. 1.>\nQuadXY 0 1\n";
    ViewerProcess v({"wide.glib", "--size", "256x64"}, dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();
    int asked = 0;
    // The hash `panel` gives is of the frame after the last `panel`: asked twice, a while apart.
    auto picture = [&] {
        for (int k = 0; k < 2; ++k) {
            std::this_thread::sleep_for(std::chrono::milliseconds(400));
            v.send("panel");
            if (!v.waitForLog("glimmer view: panel ", ++asked)) return std::string("(no answer)");
        }
        const std::string log = v.log();
        const size_t at = log.rfind(" picture=");
        return at == std::string::npos ? std::string("(none)") : log.substr(at + 9, 16);
    };
    const std::string dark = picture();
    v.send("set uR 1");
    const std::string red = picture();
    EXPECT_NE(red, dark) << v.log();
    EXPECT_EQ(picture(), red) << v.log();  // the same picture, the same hash
    v.send("set uR 0");
    EXPECT_EQ(picture(), dark) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

}  // namespace
