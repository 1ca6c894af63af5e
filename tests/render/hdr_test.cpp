// HDR render targets (a Glimmer extension): what each format keeps, sizes
// relative to the output, mip chains, and the numeric health report.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "pipeline/numeric_health.h"
#include "image/test_images.h"
#include "render_harness.h"

namespace fs = std::filesystem;
using namespace glimmer;
using namespace glimmer::testing;

namespace {

// A folder with a script that copies (or computes) into a target of the
// given format, plus the shaders it needs.
struct Scene {
    fs::path dir;
    explicit Scene(const std::string& name) {
        dir = fs::temp_directory_path() / ("glimmer_hdr_" + std::to_string(::getpid()) + "_" + name);
        fs::create_directories(dir);
        std::ofstream(dir / "copy.frag") << "#version 330 compatibility\nuniform sampler2D Src;\nin vec2 vST;\n"
                                            "void main() { gl_FragColor = texture(Src, vST); }\n";
        std::ofstream(dir / "lod.frag") << "#version 330 compatibility\nuniform sampler2D Src;\nuniform float uLod;\n"
                                           "in vec2 vST;\nvoid main() { gl_FragColor = textureLod(Src, vST, uLod); }\n";
        // Values no 8-bit target can hold, and one that is not a number.
        std::ofstream(dir / "extremes.frag")
            << "#version 330 compatibility\nin vec2 vST;\nuniform float uZero;\n"
               "void main() {\n"
               "    float x = vST.s;\n"
               "    vec3 c = x < 0.25 ? vec3(-2.0) : x < 0.5 ? vec3(70000.0) : x < 0.75 ? vec3(3.0) : vec3(0.5);\n"
               "    if (vST.t > 0.9 && x > 0.9) c = vec3(uZero / uZero);\n"
               "    gl_FragColor = vec4(c, 1.0);\n}\n";
    }
    ~Scene() { fs::remove_all(dir); }
    std::string script(const std::string& text) const {
        std::ofstream(dir / "s.glib") << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\n" << text;
        return (dir / "s.glib").string();
    }
};

float halfRound(float v) {  // the nearest half float, for comparing RGBA16F
    if (!std::isfinite(v) || v == 0) return v;
    int e = 0;
    std::frexp(v, &e);
    float step = std::ldexp(1.f, e - 11);
    return std::round(v / step) * step;
}

TEST(Hdr, FloatTargetsKeepValuesAboveOne) {
    Scene sc("keep");
    std::string s = sc.script("Texture2D 5 " + std::string(GLIMMER_SOURCE_DIR) + "/textures/hdr_scene.hdr\n"
                              "Texture2D 6 512 512 RGBA16F\nRenderToTexture 6\n"
                              "Vertex superblur.vert\nFragment copy.frag\nProgram Copy Src 5\nQuadXY 0 1\n");
    Rendered r = renderScript(testBackends().front(), s, {}, {5, 6});
    ASSERT_TRUE(r.ok) << r.error;
    const Image& in = r.floats[5];
    const Image& out = r.floats[6];
    ASSERT_EQ(out.width, 512);
    float maxIn = 0, maxOut = 0;
    size_t off = 0;
    for (size_t i = 0; i < in.f32.size(); ++i) {
        if (i % 4 == 3) continue;
        maxIn = std::max(maxIn, in.f32[i]);
        maxOut = std::max(maxOut, out.f32[i]);
        off += std::abs(out.f32[i] - halfRound(in.f32[i])) > std::abs(in.f32[i]) * 1e-3f + 1e-6f;
    }
    EXPECT_GE(maxIn, 900.f);  // the firefly
    EXPECT_EQ(maxOut, maxIn);
    EXPECT_EQ(off, 0u);
}

TEST(Hdr, EachFormatKeepsWhatItCan) {
    Scene sc("formats");
    std::string s = sc.script("Texture2D 6 64 8 RGBA8\nTexture2D 7 64 8 RGBA16F\nTexture2D 8 64 8 RGBA32F\n"
                              "Texture2D 9 64 8 R11F_G11F_B10F\n"
                              "Vertex superblur.vert\nFragment extremes.frag\nProgram X uZero <0. 0. 1.>\n"
                              "RenderToTexture 6\nQuadXY 0 1\nRenderToTexture 7\nQuadXY 0 1\n"
                              "RenderToTexture 8\nQuadXY 0 1\nRenderToTexture 9\nQuadXY 0 1\n");
    Rendered r = renderScript(testBackends().front(), s, {}, {6, 7, 8, 9});
    ASSERT_TRUE(r.ok) << r.error;
    auto at = [](const Image& img, int x) { return img.f32[(size_t(4) * size_t(img.width) + size_t(x)) * 4]; };
    // Columns: x < 16 is -2, < 32 is 70000, < 48 is 3, then 0.5.
    EXPECT_EQ(at(r.floats[6], 4), 0.f);  // RGBA8 clamps to [0,1]
    EXPECT_EQ(at(r.floats[6], 40), 1.f);
    EXPECT_EQ(at(r.floats[7], 4), -2.f);  // RGBA16F keeps signs,
    EXPECT_TRUE(std::isinf(at(r.floats[7], 20)) || at(r.floats[7], 20) == 65504.f)  // saturates past 65504
        << at(r.floats[7], 20);
    EXPECT_EQ(at(r.floats[7], 40), 3.f);
    EXPECT_EQ(at(r.floats[8], 20), 70000.f);  // RGBA32F keeps all of it
    EXPECT_EQ(at(r.floats[9], 40), 3.f);      // R11F_G11F_B10F has no sign bit
    EXPECT_LE(at(r.floats[9], 4), 0.f);
}

TEST(Hdr, HealthReportFindsEachProblem) {
    Scene sc("health");
    std::string s = sc.script("Texture2D 7 64 8 RGBA16F\nTexture2D 8 64 8 RGBA32F\nTexture2D 6 64 8 RGBA8\n"
                              "Vertex superblur.vert\nFragment extremes.frag\nProgram X uZero <0. 0. 1.>\n"
                              "RenderToTexture 7\nQuadXY 0 1\nRenderToTexture 8\nQuadXY 0 1\n"
                              "RenderToTexture 6\nQuadXY 0 1\n");
    PlanOptions options;
    options.keepTargets = {6, 7, 8};
    Diagnostics diags;
    LoadedScript loaded;
    options.includeDirs.push_back(std::string(GLIMMER_SOURCE_DIR) + "/shaders");
    ASSERT_TRUE(loadScript(s, options, diags, loaded));
    BackendChoice choice;
    ASSERT_TRUE(parseBackend(testBackends().front(), choice));
    std::string why;
    auto ctx = createContext(choice, why);
    ASSERT_TRUE(ctx) << why;
    auto r = Renderer::create([&](const char* n) { return ctx->getProcAddress(n); }, why);
    ASSERT_TRUE(r && loadAndUpload(*r, loaded, false, diags));
    r->render(UniformValues(loaded.plan), 0);
    auto report = measureHealth(*r, loaded.plan);
    ASSERT_EQ(report.size(), 3u);
    const int pixelsPerColumnBand = 16 * 8, channels = 3;
    // RGBA16F: -2 kept, 70000 saturates (Inf or 65504 by driver), the corner NaN.
    EXPECT_EQ(report[0].health.negative, size_t(pixelsPerColumnBand * channels));
    EXPECT_EQ(report[0].health.inf + report[0].health.above65504, size_t(pixelsPerColumnBand * channels));
    EXPECT_GT(report[0].health.nan, 0u);
    EXPECT_TRUE(report[0].bad());
    // RGBA32F: 70000 stays finite and is counted as above 65504.
    EXPECT_EQ(report[1].health.above65504, size_t(pixelsPerColumnBand * channels));
    EXPECT_EQ(report[1].health.inf, 0u);
    // RGBA8: nothing bad can be stored, but the clipping shows.
    EXPECT_FALSE(report[2].bad());
    EXPECT_GE(report[2].health.clippedAtOne, size_t(2 * pixelsPerColumnBand * channels));
    // ... and only the colour: alpha is 1 in every pixel of an 8-bit target and
    // never counts. At most the NaN corner (6 columns of the top row) adds to the
    // two bands of 70000 and 3.
    EXPECT_LE(report[2].health.clippedAtOne, size_t((2 * pixelsPerColumnBand + 6) * channels));
    EXPECT_NE(formatHealth(report[2]).find("at 1 (clipped if brighter)"), std::string::npos);
}

TEST(Hdr, SizesRelativeToTheOutputFollowIt) {
    Scene sc("relative");
    std::string s = sc.script("Texture2D 6 w/2 h/4 RGBA16F\nTexture2D 7 w h\nRenderToTexture 6\nClear\n"
                              "Vertex superblur.vert\nFragment copy.frag\nProgram Copy Src 7\nQuadXY 0 1\n");
    PlanOptions o;
    o.width = 100;
    o.height = 60;
    Rendered r = renderScript(testBackends().front(), s, {}, {6}, o);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.floats[6].width, 50);
    EXPECT_EQ(r.floats[6].height, 15);
}

TEST(Hdr, MipChainIsMadeAfterEachPass) {
    Scene sc("mips");
    // An 8x8 target of noise with mips, then level 1 read at texel centres.
    std::string err;
    ASSERT_TRUE(writeBmp((sc.dir / "noise.bmp").string(), makeNoiseImage(8, 8, 3), err));
    std::string s = sc.script("Texture2D 5 noise.bmp\nTexture2D 6 8 8 RGBA32F mips\nTexture2D 7 4 4 RGBA32F\n"
                              "RenderToTexture 6\nVertex superblur.vert\nFragment copy.frag\nProgram Copy Src 5\n"
                              "QuadXY 0 1\nRenderToTexture 7\nFragment lod.frag\nProgram Lod Src 6 uLod <0. 1. 4.>\n"
                              "QuadXY 0 1\n");
    Rendered r = renderScript(testBackends().front(), s, {}, {5, 7});
    ASSERT_TRUE(r.ok) << r.error;
    const Image& full = r.floats[5];
    const Image& half = r.floats[7];
    ASSERT_EQ(half.width, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            float sum = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) sum += full.f32[(size_t(2 * y + dy) * 8 + size_t(2 * x + dx)) * 4];
            EXPECT_NEAR(half.f32[(size_t(y) * 4 + size_t(x)) * 4], sum / 4, 1e-5) << x << "," << y;
        }
}

// A sampler on a unit the script never gave a texture reads nothing, also
// after a pass whose target has a mip chain: the chain is remade with that
// target bound for a moment, and it must not stay there (issue 40's sampled
// mutant renderer.cpp:195 unbound it from no target at all, and the next
// pass's sampler on unit 0 read the white target instead of black).
TEST(Hdr, AUnitTheScriptGaveNoTextureReadsNothingAfterAMipChainIsMade) {
    Scene sc("mipsunbound");
    std::ofstream(sc.dir / "white.frag") << "#version 330 compatibility\nvoid main() { gl_FragColor = vec4(1.); }\n";
    std::string s = sc.script("Texture2D 6 8 8 RGBA32F mips\nTexture2D 7 8 8 RGBA32F\n"
                              "RenderToTexture 6\nVertex superblur.vert\nFragment white.frag\nProgram White\nQuadXY 0 1\n"
                              "RenderToTexture 7\nFragment copy.frag\nProgram Stray Src 0\nQuadXY 0 1\n");
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Rendered r = renderScript(backend, s, {}, {6, 7});
        ASSERT_TRUE(r.ok) << r.error;
        ASSERT_EQ(r.floats[6].width, 8);
        ASSERT_EQ(r.floats[7].width, 8);
        long white = 0, black = 0;
        for (size_t i = 0; i < r.floats[6].f32.size(); ++i) white += i % 4 != 3 && r.floats[6].f32[i] == 1.f;
        for (size_t i = 0; i < r.floats[7].f32.size(); ++i) black += i % 4 != 3 && r.floats[7].f32[i] == 0.f;
        EXPECT_EQ(white, 8 * 8 * 3);  // the first pass drew
        EXPECT_EQ(black, 8 * 8 * 3);  // and the second read nothing of it
    }
}

// The same after a float read-back between two frames (the viewer's health
// check and probe read targets as floats after each new picture): the
// target read is bound for the read, and must not stay bound after it
// (issue 40's sampled mutant renderer_readback.cpp:34 left texture 1 bound,
// the first pass's white target here, and the next frame's sampler on
// unit 0 read white where it read black).
TEST(Hdr, AUnitTheScriptGaveNoTextureReadsNothingAfterAFloatReadBack) {
    Scene sc("readbackunbound");
    std::ofstream(sc.dir / "white.frag") << "#version 330 compatibility\nvoid main() { gl_FragColor = vec4(1.); }\n";
    std::string s = sc.script("Texture2D 6 8 8 RGBA32F\nTexture2D 7 8 8 RGBA32F\n"
                              "RenderToTexture 6\nVertex superblur.vert\nFragment white.frag\nProgram White\nQuadXY 0 1\n"
                              "RenderToTexture 7\nFragment copy.frag\nProgram Stray Src 0\nQuadXY 0 1\n");
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Diagnostics diags;
        LoadedScript loaded;
        PlanOptions options;
        options.keepTargets = {6, 7};
        options.includeDirs.push_back(std::string(GLIMMER_SOURCE_DIR) + "/shaders");
        ASSERT_TRUE(loadScript(s, options, diags, loaded) && !diags.hasErrors());
        Rig rig = makeRig(backend, loaded, diags);
        ASSERT_TRUE(rig.renderer) << rig.error;
        Renderer* renderer = rig.renderer.get();
        UniformValues values(loaded.plan);
        auto blackOf = [&](int unit) {
            Image img = renderer->readTextureFloat(loaded.plan.finalUnits.at(unit));
            long black = 0;
            for (size_t i = 0; i < img.f32.size(); ++i) black += i % 4 != 3 && img.f32[i] == 0.f;
            return black;
        };
        for (int frame = 0; frame < 2; ++frame) {
            SCOPED_TRACE("frame " + std::to_string(frame));
            renderer->render(values, 0.0);
            EXPECT_EQ(blackOf(6), 0);          // the first pass drew white
            EXPECT_EQ(blackOf(7), 8 * 8 * 3);  // and the second read nothing, after a read-back too
        }
    }
}

TEST(Hdr, UnknownFormatIsAnError) {
    Scene sc("badformat");
    std::string s = sc.script("Texture2D 6 8 8 RGB10\n");
    Diagnostics d;
    LoadedScript l;
    ASSERT_TRUE(loadScript(s, {}, d, l));
    ASSERT_TRUE(d.hasErrors());
    EXPECT_EQ(d.all().back().message,
              "'RGB10' is not a texture format (RGBA8, RGBA16F, RGBA32F, R11F_G11F_B10F) or 'mips'");
}

}  // namespace

namespace {

// The LearnOpenGL bright pass's sanitize. On llvmpipe a NaN or Inf never
// reaches the blur through the threshold test (NaN > t is false, and
// GL_LINEAR turns an Inf texel into NaN: Inf * 0 in the filter), so what
// spreads is a finite value too large for half floats: a 1e30 firefly. Without
// sanitize the blur carries it along its 9 taps; with it the bright pass caps
// it at 65504 and nothing downstream leaves the half-float range.
long overHalf(const Image& img) {
    long n = 0;
    for (size_t i = 0; i < img.f32.size(); ++i) n += i % 4 != 3 && !(std::fabs(img.f32[i]) <= 65504.f);
    return n;
}

TEST(HdrSanitize, AFireflyTooBigForHalfFloatsDoesNotSpread) {
    Scene sc("sanitize");
    std::ofstream(sc.dir / "spot.frag")
        << "#version 330 compatibility\nin vec2 vST;\n"
           "void main() {\n"
           "    ivec2 p = ivec2(gl_FragCoord.xy);\n"
           "    float v = (p.x == 16 && p.y == 16) ? 1e30 : 2.0;\n"
           "    gl_FragColor = vec4(v, v, v, 1.0);\n}\n";
    for (bool sanitize : {false, true}) {
        std::string s = sc.script(std::string("Texture2D 5 32 32 RGBA32F\nTexture2D 6 32 32 RGBA32F\n"
                                              "Texture2D 7 32 32 RGBA32F\nTexture2D 8 32 32 RGBA32F\n"
                                              "Vertex quad.vert\nRenderToTexture 5\nFragment spot.frag\n"
                                              "Program N\nQuadXY 0 1\n"
                                              "RenderToTexture 6 7\nFragment lo_scene.frag\n"
                                              "Program Scene HdrUnit 5 uThreshold <0. 1. 20.> uSanitize <") +
                                  (sanitize ? "true" : "false") +
                                  ">\nQuadXY 0 1\nRenderToTexture 8\nFragment gauss9.frag\n"
                                  "Program B ImageUnit 7 uHorizontal 1\nQuadXY 0 1\n");
        PlanOptions o;
        o.includeDirs.push_back(std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom");
        Rendered r = renderScript(testBackends().front(), s, {}, {5, 8}, o);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(overHalf(r.floats[5]), 3);  // the one firefly, in r, g and b
        EXPECT_EQ(overHalf(r.floats[8]), sanitize ? 0 : 9 * 3) << (sanitize ? "sanitized" : "raw");
    }
}

}  // namespace
