// The viewer opens a script whose images and model are missing (stand-ins
// are on by default in view): it saves what `render --stand-ins` draws, and
// with --no-stand-ins it reports the missing files instead.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "viewer_process.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;

namespace {

struct StandInProject {
    glimmer::testing::TestFolder folder{"glimmer_standin_view_"};
    fs::path dir = folder.path;
    StandInProject() {
        fs::path data = fs::path(GLIMMER_SOURCE_DIR) / "tests/data/cli";
        for (auto f : {"stand_ins.glib", "st.vert", "stand_in.frag"}) fs::copy_file(data / f, dir / f);
    }
};

TEST(ViewerStandIns, OnByDefaultAndSavesWhatRenderDraws) {
    StandInProject p;
    ViewerProcess v({"stand_ins.glib", "--size", "128x128"}, p.dir);
    ASSERT_TRUE(v.waitForLog("glimmer view: loaded")) << v.log();
    EXPECT_NE(v.log().find("stand_ins.glib:17:5: warning: cannot find model 'lost_model.obj'"), std::string::npos)
        << v.log();
    v.send("save view.png");
    ASSERT_TRUE(waitForFile(p.dir / "view.png")) << v.log();
    EXPECT_EQ(v.quit(), 0) << v.log();
    std::string cmd = std::string(GLIMMER_BIN) + " render " + (p.dir / "stand_ins.glib").string() +
                      " --stand-ins --size 128x128 -o " + (p.dir / "render.png").string() + " 2>/dev/null";
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_EQ(readBytes(p.dir / "view.png"), readBytes(p.dir / "render.png"));
}

TEST(ViewerStandIns, NoStandInsReportsTheMissingFiles) {
    StandInProject p;
    ViewerProcess v({"stand_ins.glib", "--size", "128x128", "--no-stand-ins"}, p.dir);
    ASSERT_TRUE(v.waitForLog("failed; keeping the last good picture")) << v.log();
    EXPECT_NE(v.log().find("stand_ins.glib:17:5: error: cannot find model 'lost_model.obj'"), std::string::npos)
        << v.log();
    v.quit();
}

}  // namespace
