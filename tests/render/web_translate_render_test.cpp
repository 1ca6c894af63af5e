// The translation for WebGL 2 (shader/web_translate.h) on a real OpenGL ES
// 3.0 context (egl-gles: Mesa's llvmpipe, WebGL 2's level): what it writes
// compiles and links there with the names the renderer looks up, and a
// compatibility-profile script drawn on ES through it is the picture the
// desktop draws from the untranslated shaders.
#include <algorithm>
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "backends/context.h"
#include "common/test_folder.h"
#include "gl/gl_api.h"
#include "gl/shader_build.h"
#include "render_harness.h"
#include "shader/compat_builtins.h"
#include "shader/web_translate.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

const char* kVertex = R"(attribute vec3 Tangent;
varying vec2 vST;
varying vec3 vN;
uniform float uScale;
void main() {
    float x = 1;
    vST = gl_MultiTexCoord0.st * uScale * x;
    vN = normalize(gl_NormalMatrix * gl_Normal) + 0. * Tangent;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";
const char* kFragment = R"(varying vec2 vST;
varying vec3 vN;
uniform sampler2D uTex;
uniform float uAdd;
void main() {
    float k = 2;
    gl_FragColor = vec4(texture2D(uTex, vST).rgb * k + uAdd + vN, 1);
}
)";

std::string translated(const char* text, WebStage stage) {
    Diagnostics diags;
    WebTranslation t = translateForWeb({text, stage, "test.glsl", ""}, diags);
    EXPECT_TRUE(t.ok) << (diags.all().empty() ? "" : diags.all().front().message);
    return t.text;
}

TEST(WebTranslateOnEs, TheTranslationCompilesAndLinksOnOpenGlEs) {
    std::string why;
    auto context = createContext(BackendChoice::EglGles, why);
    ASSERT_TRUE(context) << "backend 'egl-gles' is unusable: " << why;
    GlApi gl;
    ASSERT_TRUE(loadGlApi(gl, [&](const char* n) { return context->getProcAddress(n); }, why)) << why;
    ASSERT_TRUE(gl.es) << "egl-gles made a desktop context";
    std::string vertex = translated(kVertex, WebStage::Vertex), fragment = translated(kFragment, WebStage::Fragment);
    unsigned program = buildPlainProgram(gl, vertex, fragment);
    ASSERT_NE(program, 0u) << "did not compile or link on OpenGL ES:\n" << vertex << "\n" << fragment;
    // The names the renderer and the script's uniform ranges look up.
    for (const char* name : {"uScale", "uAdd", "uTex", "glimmer_ModelViewProjectionMatrix", "glimmer_NormalMatrix"})
        EXPECT_GE(gl.GetUniformLocation(program, name), 0) << name;
    for (CompatFeed f : {CompatFeed::Vertex, CompatFeed::NormalAttrib, CompatFeed::MultiTexCoord0})
        EXPECT_EQ(gl.GetAttribLocation(program, std::string(compatBuiltin(f).name).c_str()), compatBuiltin(f).location)
            << compatBuiltin(f).name;
    gl.DeleteProgram(program);
}

long litPixels(const Image& img) {
    long n = 0;
    for (size_t i = 0; i < img.u8.size(); i += 4)
        if (img.u8[i] > 60 || img.u8[i + 1] > 60) ++n;
    return n;
}

// Why 2 steps: both are llvmpipe, but glslang folds constants the driver
// computes at run time (normalize(vec3(1)), 1/3), a last-bit difference in
// float that one rounding to 8 bits can turn into 1 step, and pow(d, 20)
// magnifies it near d = 1. More than that is a translation that changed
// the arithmetic.
constexpr int kStepsAllowed = 2;

void expectSamePicture(const Rendered& desktop, const Rendered& es, int size) {
    ASSERT_TRUE(desktop.ok) << desktop.error;
    ASSERT_TRUE(es.ok) << es.error;
    ASSERT_EQ(es.screen.width, size);
    EXPECT_GT(litPixels(desktop.screen), long(size) * size / 10) << "an empty picture proves nothing";
    Difference d = compareRgb(desktop.screen, es.screen);
    EXPECT_LE(d.maxSteps, kStepsAllowed) << d.maxSteps << " steps at (" << d.x << ", " << d.y << "), "
                                         << d.pixelsOver1 << " pixels differ by more than 1";
    EXPECT_LE(d.pixelsOver1, long(size) * size / 1000) << "more than 0.1% of the pixels differ by more than 1 step";
    std::cout << "[ figures  ] ES through the translation against the desktop: max " << d.maxSteps << " steps, "
              << d.pixelsOver1 << " pixels over 1\n";
}

// A classroom script in the compatibility profile (tests/data/web): a
// pattern pass into a target, then a lit sphere and torus sampling it with
// texture2D, on desktop OpenGL as written and on OpenGL ES through the
// translation.
TEST(WebTranslateOnEs, ACompatibilityScriptDrawsTheDesktopsPicture) {
    PlanOptions options;
    options.width = options.height = 96;
    const std::string script = std::string(GLIMMER_TEST_DATA) + "/web/compat_scene.glib";
    const std::vector<std::string> sets{"uStripes=8", "uShine=.7"};
    Rendered desktop = renderScript("osmesa", script, sets, {}, options);
    Rendered es = renderScript("egl-gles", script, sets, {}, options);
    expectSamePicture(desktop, es, 96);
    // The pattern pass went through: the sphere is striped, not flat.
    ASSERT_TRUE(es.ok);
    int levels = 0;
    for (int x = 10, last = -1; x < 50; ++x) {
        int r = es.screen.u8[(size_t(40) * 96 + x) * 4];
        if (last >= 0 && std::abs(r - last) > 20) ++levels;
        last = r;
    }
    EXPECT_GT(levels, 1) << "no stripes across the sphere";
}

// Issue 37: a global const set from a uniform (NVIDIA's leniency, FogDragon's
// dragon.vert:29) runs in the page as on the desktop: the 'const' dropped,
// the value set when the shader starts, the same picture at two settings.
TEST(WebTranslateOnEs, AGlobalConstFromAUniformDrawsTheDesktopsPicture) {
    PlanOptions options;
    options.width = options.height = 16;
    const std::string script = std::string(GLIMMER_TEST_DATA) + "/cli/const_global.glib";
    for (const char* set : {"uK=.5", "uK=.2"}) {
        Rendered desktop = renderScript("osmesa", script, {set}, {}, options);
        Rendered es = renderScript("egl-gles", script, {set}, {}, options);
        ASSERT_TRUE(es.ok) << set;
        expectSamePicture(desktop, es, 16);
        EXPECT_NEAR(es.screen.u8[0], std::string(set) == "uK=.5" ? 255 : 102, 1) << set;  // red = 2 uK
    }
}

// glman classroom scripts whose shaders pass the colour through
// gl_FrontColor / gl_Color and use the built-ins (tests/data/glman), drawn
// through the translation on OpenGL ES and as written on the desktop.
class GlmanScriptOnEs : public ::testing::TestWithParam<const char*> {};

TEST_P(GlmanScriptOnEs, DrawsTheDesktopsPicture) {
    PlanOptions options;
    options.width = options.height = 96;
    const std::string script = std::string(GLIMMER_TEST_DATA) + "/glman/" + GetParam() + ".glib";
    expectSamePicture(renderScript("osmesa", script, {}, {}, options), renderScript("egl-gles", script, {}, {}, options), 96);
}

INSTANTIATE_TEST_SUITE_P(Scripts, GlmanScriptOnEs,
                         ::testing::Values("cone_cylinder_disk", "quad_texture", "teapot", "texture3d", "cubemap_axes",
                                           "uniform_forms"));

// The seed bloom (scripts/bloom.glib, compatibility GLSL, two passes) on
// OpenGL ES through the translation: the picture `--backend osmesa` draws.
TEST(WebTranslateOnEs, TheSeedBloomDrawsTheDesktopsPicture) {
    PlanOptions options;
    options.width = options.height = 128;
    const std::string script = std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib";
    const std::vector<std::string> sets{"uAdd=2", "uHalfSize=5"};
    expectSamePicture(renderScript("osmesa", script, sets, {}, options), renderScript("egl-gles", script, sets, {}, options),
                      128);
}

// OpenGL ES reads a float target only as floats; the renderer turns them
// into bytes as the desktop's glGetTexImage does: each value clamped to 0..1,
// times 255, rounded. What the page's viewer saves when a float target is on
// show ("S"). Values below 0, between, and over 1, against the CPU's clamp of
// the floats read back (issue 40: a sampled mutant made those below 0 white).
TEST(WebTranslateOnEs, AFloatTargetReadAsBytesIsClampedAsOnTheDesktop) {
    TestFolder dir("glimmer_es_float_bytes_");
    std::ofstream(dir.path / "v.vert") << "#version 330 compatibility\nout vec2 vST;\n"
                                          "void main() { vST = gl_MultiTexCoord0.st; gl_Position = ftransform(); }\n";
    std::ofstream(dir.path / "f.frag") << "#version 330 compatibility\nin vec2 vST;\n"
                                          "void main() { gl_FragColor = vec4(vST.s * 4. - 2., -1., .5, 3.); }\n";
    std::ofstream(dir.path / "s.glib") << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nTexture2D 5 16 16 RGBA16F\n"
                                          "RenderToTexture 5\nVertex v.vert\nFragment f.frag\nProgram P\nQuadXY 0 1\n"
                                          "RenderToTexture\n";
    PlanOptions options;
    options.width = options.height = 16;
    for (const char* backend : {"egl-gles", "osmesa"}) {
        SCOPED_TRACE(backend);
        Rendered r = renderScript(backend, (dir.path / "s.glib").string(), {}, {5}, options);
        ASSERT_TRUE(r.ok) << r.error;
        const Image& bytes = r.units[5];
        const Image& floats = r.floats[5];
        ASSERT_EQ(bytes.u8.size(), 16u * 16u * 4u);
        ASSERT_EQ(floats.f32.size(), bytes.u8.size());
        int below = 0, over = 0, worst = 0;
        for (size_t i = 0; i < bytes.u8.size(); ++i) {
            const float v = floats.f32[i];
            below += v < 0, over += v > 1;
            const int want = int(std::nearbyint(std::clamp(v, 0.f, 1.f) * 255.f));
            worst = std::max(worst, std::abs(int(bytes.u8[i]) - want));
        }
        EXPECT_GT(below, 16 * 16) << "the picture has values below 0";
        EXPECT_GT(over, 16 * 16) << "and over 1";
        EXPECT_EQ(worst, 0) << "bytes unlike the clamped floats";
    }
}

}  // namespace
