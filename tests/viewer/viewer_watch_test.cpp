// A watch in the viewer (issue 28): the same picture `render --watch` writes,
// drawn again as a slider moves; the probe reads its floats; a refusal is
// said as the command line says it; watch off brings the picture back; the
// panel's watch controls, clicked and typed into, do what the commands do.
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <thread>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "seed_project.h"
#include "viewer_process.h"
#include "x11_driver.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;

namespace {

struct Project : SeedProject {
    Project() : SeedProject("glimmer_viewer_watch_") {}
};

int render(const Project& p, const std::string& args) {
    std::string cmd = fmt::format("cd {} && {} render bloom.glib --size 256x256 {} 2>/dev/null >/dev/null", p.dir.string(),
                                  GLIMMER_BIN, args);
    int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The float at pixel (x, y) (row 0 at the top) of a PFM, channel c.
float pfmAt(const fs::path& path, int x, int y, int c) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int w = 0, h = 0;
    float scale = 0;
    in >> magic >> w >> h >> scale;
    in.get();
    in.seekg(std::streamoff((size_t(h - 1 - y) * size_t(w) + size_t(x)) * 3 + size_t(c)) * 4, std::ios::cur);
    float v = 0;
    in.read(reinterpret_cast<char*>(&v), 4);
    return v;
}

TEST(ViewerWatch, FollowsASliderAsRenderWatchDrawsItAndTheProbeReadsItsFloats) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "256x256"}, p.dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();
    v.send("watch bloom.frag:12 rgbblur");
    ASSERT_TRUE(v.waitForLog("glimmer view: watch bloom.frag:12 rgbblur, pass 2 (Program Bloom): vec3 over 256x256"))
        << v.log();
    v.send("set uHalfSize 5");
    v.send("save w5.png");
    v.send("probe 100 60");
    v.send("probe 128 60");
    v.send("set uHalfSize 9");
    v.send("save w9.png");
    v.send("probe 128 60");  // the same pixel of a new picture: read again, not the last answer
    // A slider of the watched pass alone: the blur that feeds it is kept, not drawn again.
    v.send("watch bloom.frag:13 rgb + uAdd*rgbblur");
    v.send("set uAdd 3");
    v.send("save wadd.png");
    v.send("watch off");
    v.send("save plain.png");
    ASSERT_TRUE(waitForFile(p.dir / "plain.png")) << v.log();
    ASSERT_TRUE(v.waitForLog("glimmer view: probe (100, 60) of the watch: rgbblur = vec3(")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();

    ASSERT_EQ(render(p, "--set uHalfSize=5 --watch bloom.frag:12:rgbblur -o r5.png"), 0);
    ASSERT_EQ(render(p, "--set uHalfSize=9 --watch bloom.frag:12:rgbblur -o r9.png"), 0);
    ASSERT_EQ(render(p, "--set uHalfSize=9 --set uAdd=3 --watch 'bloom.frag:13:rgb + uAdd*rgbblur' -o radd.png"), 0);
    ASSERT_EQ(render(p, "--set uHalfSize=9 --set uAdd=3 -o plain_render.png"), 0);
    EXPECT_EQ(readBytes(p.dir / "wadd.png"), readBytes(p.dir / "radd.png"));
    EXPECT_EQ(readBytes(p.dir / "w5.png"), readBytes(p.dir / "r5.png"));
    EXPECT_EQ(readBytes(p.dir / "w9.png"), readBytes(p.dir / "r9.png"));
    EXPECT_NE(readBytes(p.dir / "w5.png"), readBytes(p.dir / "w9.png")) << "the watch follows the slider";
    EXPECT_EQ(readBytes(p.dir / "plain.png"), readBytes(p.dir / "plain_render.png")) << "watch off: the picture";

    // Every component, with a float's digits: the values render --watch writes.
    ASSERT_EQ(render(p, "--set uHalfSize=5 --watch bloom.frag:12:rgbblur -o r5.pfm"), 0);
    const std::string want = fmt::format("probe (100, 60) of the watch: rgbblur = vec3({:.9g}, {:.9g}, {:.9g})\n",
                                         pfmAt(p.dir / "r5.pfm", 100, 60, 0), pfmAt(p.dir / "r5.pfm", 100, 60, 1),
                                         pfmAt(p.dir / "r5.pfm", 100, 60, 2));
    EXPECT_NE(v.log().find(want), std::string::npos) << want << v.log();
    ASSERT_EQ(render(p, "--set uHalfSize=9 --watch bloom.frag:12:rgbblur -o r9.pfm"), 0);
    auto probed = [&](const char* pfm) {
        return fmt::format("probe (128, 60) of the watch: rgbblur = vec3({:.9g}, {:.9g}, {:.9g})\n",
                           pfmAt(p.dir / pfm, 128, 60, 0), pfmAt(p.dir / pfm, 128, 60, 1), pfmAt(p.dir / pfm, 128, 60, 2));
    };
    const std::string want5 = probed("r5.pfm"), want9 = probed("r9.pfm");
    EXPECT_NE(want9, want5) << "the two settings must differ at that pixel for this to test anything";
    EXPECT_NE(v.log().find(want5), std::string::npos) << want5 << v.log();
    EXPECT_NE(v.log().find(want9), std::string::npos) << want9 << v.log();
}

TEST(ViewerWatch, ARefusalIsSaidAsTheCommandLineSaysItAndAnEditIsWatchedAgain) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "128x128"}, p.dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();
    v.send("watch bloom.frag:11 rgbblur");
    EXPECT_TRUE(v.waitForLog("glimmer view: bloom.frag:11:51: error: 'rgbblur' is not in scope at line 11: watch a "
                             "variable declared before this line in the same block or one around it, a uniform, or an "
                             "input\n"))
        << v.log();
    v.send("watch bloom.frag:13 rgbblur * 0.5");
    ASSERT_TRUE(v.waitForLog("glimmer view: watch bloom.frag:13 rgbblur * 0.5")) << v.log();
    // The student edits the shader: the watch is set up again on the new text.
    std::ifstream in(p.dir / "bloom.frag");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const std::string from = "vec3 rgbblur = texture( BlurUnit, vST ).rgb;";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "vec3 rgbblur = texture( BlurUnit, vST ).rgb * 0.25;");
    std::ofstream(p.dir / "bloom.frag") << text;
    v.send("reload");
    v.send("save edited.png");
    ASSERT_TRUE(waitForFile(p.dir / "edited.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    std::string cmd = fmt::format("cd {} && {} render bloom.glib --size 128x128 --watch 'bloom.frag:13:rgbblur * 0.5' "
                                  "-o edited_render.png 2>/dev/null >/dev/null", p.dir.string(), GLIMMER_BIN);
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(readBytes(p.dir / "edited.png"), readBytes(p.dir / "edited_render.png"));
}

// The panel's watch controls used as a person would (xdotool clicks and
// typing on the virtual X server), each found with the viewer's `where`:
// the field typed into and Watch, the range's fields and Fix range, Own
// range, Stop; each does what its command does (the page: tests/web/watch.sh).
TEST(ViewerWatch, ThePanelsWatchControlsClickedDoWhatTheirCommandsDo) {
    Project p;
    ViewerProcess v({"bloom.glib", "--size", "256x256"}, p.dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: ui scale")) << v.log();
    auto x = findViewer(p.dir);
    ASSERT_TRUE(x) << v.log();
    std::map<std::string, int> asked;  // how often each control's place was asked for
    auto countIn = [](const std::string& log, const std::string& needle) {
        int n = 0;
        for (size_t at = log.find(needle); at != std::string::npos; at = log.find(needle, at + 1)) ++n;
        return n;
    };
    // Clicks `name` at `fraction` of its width, where the viewer says it is now.
    // Asked again while the panel is not drawn yet (a loaded machine: the
    // first frame's panel comes after the line the test starts on).
    auto click = [&](const std::string& name, double fraction = 0.5) {
        const std::string said = "glimmer view: where " + name + " at ";
        bool found = false;
        for (int attempt = 0; attempt < 10 && !found; ++attempt) {
            v.send("where " + name);
            found = v.waitForLog(said, asked[name] + 1, std::chrono::seconds(3));
        }
        if (!found) return false;
        const std::string log = v.log();
        asked[name] = countIn(log, said);
        double cx = 0, cy = 0, w = 0, h = 0;
        std::istringstream in(log.substr(log.rfind(said) + said.size()));
        if (!(in >> cx >> cy >> w >> h)) return false;
        // Press and release a few frames apart, and a pause after: ImGui 1.86 reads the button per
        // frame, and a loaded machine's slow frame lost a quick click (the field then never took
        // the typed text, which went to the window's keys: three reloads).
        xdotool(*x, fmt::format("mousemove --window {} {} {} sleep 0.2 mousedown 1 sleep 0.3 mouseup 1 sleep 0.5", x->window,
                                int(cx + fraction * w), int(cy + h / 2)));
        return true;
    };
    // Clicks the field `name` until the panel says it holds the keyboard
    // (`panel`'s active=): under the sanitizers a frame can take long
    // enough to lose a click, and the text typed then went to the window's
    // keys (CI saw three reloads and an empty field). Then selects what the
    // field holds (Ctrl+A, held over a few frames) so `text` replaces it.
    auto typeInto = [&](const std::string& name, const std::string& text, double fraction = 0.5) {
        std::string word = name;
        for (size_t at; (at = word.find(' ')) != std::string::npos;) word.replace(at, 1, "%20");
        bool active = false;
        for (int attempt = 0; attempt < 5 && !active; ++attempt) {
            if (!click(name, fraction)) return false;
            const std::string before = v.log();
            v.send("panel");
            if (!v.waitForLog("glimmer view: panel ", countIn(before, "glimmer view: panel ") + 1, std::chrono::seconds(10)))
                continue;
            active = v.log().find(" active=" + word + " ", before.size()) != std::string::npos;
        }
        if (!active) return false;
        xdotool(*x, "keydown ctrl sleep 0.1 keydown a sleep 0.3 keyup a sleep 0.1 keyup ctrl sleep 0.2");
        xdotool(*x, fmt::format("type --delay 30 '{}'", text));  // `type` takes every word after it as text
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        return true;
    };
    ASSERT_TRUE(typeInto("Watch", "bloom.frag:12 rgbblur")) << v.log();
    ASSERT_TRUE(click("Watch button")) << v.log();
    ASSERT_TRUE(v.waitForLog("glimmer view: watch bloom.frag:12 rgbblur, pass 2 (Program Bloom): vec3 over 256x256: "
                             "range 0 .. 1 (its own)")) << v.log();
    for (auto [fraction, value] : {std::pair{0.2, "0.25"}, std::pair{0.7, "0.75"}})
        ASSERT_TRUE(typeInto("Watch range", value, fraction)) << v.log();
    ASSERT_TRUE(click("Fix range")) << v.log();
    ASSERT_TRUE(v.waitForLog("vec3 over 256x256: range 0.25 .. 0.75 (fixed)")) << v.log();
    ASSERT_TRUE(click("Own range")) << v.log();
    ASSERT_TRUE(v.waitForLog("range 0 .. 1 (its own)", 2)) << v.log();
    ASSERT_TRUE(click("Stop")) << v.log();
    ASSERT_TRUE(v.waitForLog("glimmer view: watch: off")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
}

}  // namespace
