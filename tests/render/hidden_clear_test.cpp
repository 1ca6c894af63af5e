// A Clear under a quad that covers the whole screen is skipped
// (plan/hidden_clears.h) only when skipping it changes no pixel: a
// fragment shader that discards keeps the Clear, so the background shows
// where it discards.
#include <fstream>

#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

// Red background; a screen-filling quad drawing green, discarding the left
// half when `discardLeft`.
Rendered halfDiscarded(bool discardLeft) {
    TestFolder dir("glimmer_hidden_clear_");
    std::ofstream(dir.path / "q.vert") << "#version 330 compatibility\nout vec2 vST;\n"
                                          "void main() { vST = gl_MultiTexCoord0.st;\n"
                                          "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n";
    std::ofstream(dir.path / "q.frag") << "#version 330 compatibility\nin vec2 vST;\nvoid main() {\n"
                                       << (discardLeft ? "  if (vST.s < .5) discard;\n" : "")
                                       << "  gl_FragColor = vec4(0., 1., 0., 1.); }\n";
    std::ofstream(dir.path / "s.glib") << "Ortho -1 1 -1 1\nBackground 1 0 0\nClear\nVertex q.vert\nFragment q.frag\n"
                                          "Program Q\nQuadXY 0 2\n";
    PlanOptions options;
    options.width = options.height = 32;
    return renderScript(testBackends().front(), (dir.path / "s.glib").string(), {}, {}, options);
}

int redAt(const Image& img, int x, int y) { return img.u8[(size_t(y) * img.width + x) * 4]; }
int greenAt(const Image& img, int x, int y) { return img.u8[(size_t(y) * img.width + x) * 4 + 1]; }

TEST(HiddenClear, TheBackgroundShowsWhereTheCoveringQuadDiscards) {
    Rendered r = halfDiscarded(true);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(redAt(r.screen, 4, 16), 255);    // left: the Clear's red
    EXPECT_EQ(greenAt(r.screen, 4, 16), 0);
    EXPECT_EQ(redAt(r.screen, 28, 16), 0);     // right: the quad's green
    EXPECT_EQ(greenAt(r.screen, 28, 16), 255);
}

TEST(HiddenClear, ACoveringQuadThatDiscardsNothingLeavesNoBackground) {
    Rendered r = halfDiscarded(false);
    ASSERT_TRUE(r.ok) << r.error;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(greenAt(r.screen, x, y), 255) << x << "," << y;
}

}  // namespace
