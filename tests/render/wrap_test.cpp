// Wrap (a Glimmer extension): a bright column at a target's right edge,
// blurred along s. With GL_REPEAT (no Wrap, glman's way) the blur's taps past
// the right edge read the left edge and the other way round, so glow appears
// on the left; with `Wrap clamp` the left edge stays dark.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "render_harness.h"

namespace fs = std::filesystem;
using namespace glimmer;
using namespace glimmer::testing;

namespace {

struct EdgeScene {
    fs::path dir;
    EdgeScene() {
        dir = fs::temp_directory_path() / ("glimmer_wrap_" + std::to_string(::getpid()));
        fs::create_directories(dir);
        std::ofstream(dir / "edge.frag") << "#version 330 compatibility\n"
                                            "void main() {\n"
                                            "    float v = int(gl_FragCoord.x) == 31 ? 10.0 : 0.0;\n"
                                            "    gl_FragColor = vec4(v, v, v, 1.0);\n}\n";
    }
    ~EdgeScene() { fs::remove_all(dir); }
    // The spot on unit 5, blurred along s by gauss9.frag into unit 6.
    std::string script(const std::string& wrapLine) const {
        std::ofstream(dir / "s.glib") << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\n" << wrapLine
                                      << "Texture2D 5 32 32 RGBA32F\nTexture2D 6 32 32 RGBA32F\n"
                                         "Vertex quad.vert\nRenderToTexture 5\nFragment edge.frag\nProgram Edge\n"
                                         "QuadXY 0 1\nRenderToTexture 6\nFragment gauss9.frag\n"
                                         "Program Blur ImageUnit 5 uHorizontal 1\nQuadXY 0 1\n";
        return (dir / "s.glib").string();
    }
};

// Red of texel (x, y) of a float read-back.
float red(const Image& img, int x, int y) { return img.f32[(size_t(y) * size_t(img.width) + size_t(x)) * 4]; }

TEST(Wrap, ClampKeepsGlowOffTheOppositeEdge) {
    EdgeScene sc;
    PlanOptions o;
    o.includeDirs.push_back(std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom");
    for (const std::string& backend : testBackends()) {
        for (const char* wrap : {"", "Wrap repeat\n", "Wrap clamp\n", "Wrap mirror\n"}) {
            Rendered r = renderScript(backend, sc.script(wrap), {}, {6}, o);
            ASSERT_TRUE(r.ok) << r.error;
            const Image& blur = r.floats[6];
            ASSERT_EQ(blur.width, 32);
            bool repeats = std::string(wrap).empty() || std::string(wrap) == "Wrap repeat\n";
            SCOPED_TRACE(backend + " '" + wrap + "'");
            for (int y : {0, 16, 31}) {
                // The glow itself is there either way: 10 * the centre weight and more.
                EXPECT_GT(red(blur, 31, y), 10 * 0.227f) << y;
                EXPECT_GT(red(blur, 27, y), 10 * 0.016f * 0.9f) << y;
                if (repeats) {
                    // Texel 0 reads texel 31 one texel to its left: 10 * 0.1946.
                    EXPECT_NEAR(red(blur, 0, y), 10 * 0.1945946f, 1e-3f) << y;
                    EXPECT_GT(red(blur, 3, y), 0.1f) << y;
                } else {
                    EXPECT_EQ(red(blur, 0, y), 0.f) << y;
                    EXPECT_EQ(red(blur, 3, y), 0.f) << y;
                }
            }
            // Clamping repeats the edge texel past it, mirroring reflects the
            // column back: both brighten the edge more than repeat does.
            if (!repeats) {
                EXPECT_GT(red(blur, 31, 16), 10 * (0.227f + 0.1945f)) << wrap;
            }
        }
    }
}

}  // namespace
