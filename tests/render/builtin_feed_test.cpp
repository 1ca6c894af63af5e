// The way WebGL 2 draws, checked on the desktop: a program that declares the
// built-ins' stand-ins (glimmer_Vertex, glimmer_NormalMatrix, ...:
// shader/compat_builtins.h) is fed them as attributes and uniforms
// (gl/builtin_feed.h), and draws the same pixels as its compatibility-profile
// twin fed by the fixed-function state: a lit, textured-coordinate sphere
// under a perspective, moved by the script's transforms, in a colour.
#include <gtest/gtest.h>

#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

// The scene (tests/data/web): lit_compat.glib with compatibility-profile
// shaders, lit_es.glib with their GLSL ES twins; the page's test draws the
// second in a browser.
Rendered renderWith(const std::string& backend, const std::string& which) {
    PlanOptions options;
    options.width = options.height = 96;
    return renderScript(backend, std::string(GLIMMER_TEST_DATA) + "/web/lit_" + which + ".glib", {}, {}, options);
}

long litPixels(const Image& img) {
    long n = 0;
    for (size_t i = 0; i < img.u8.size(); i += 4)
        if (img.u8[i] > 60 || img.u8[i + 1] > 60) ++n;
    return n;
}

TEST(BuiltinFeed, AFedProgramDrawsWhatTheFixedFunctionStateDraws) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE("backend " + backend);
        Rendered compat = renderWith(backend, "compat");
        Rendered fed = renderWith(backend, "es");
        ASSERT_TRUE(compat.ok) << compat.error;
        ASSERT_TRUE(fed.ok) << fed.error;
        // Not an empty picture twice: both objects are there.
        EXPECT_GT(litPixels(compat.screen), 96 * 96 / 10);
        Difference d = compareRgb(compat.screen, fed.screen);
        EXPECT_LE(d.maxSteps, 1) << d.maxSteps << " steps at (" << d.x << ", " << d.y << "), " << d.pixelsOver1
                                 << " pixels differ by more than 1";
    }
}

// On OpenGL ES 3.0 (egl-gles: WebGL 2's level, Mesa's surfaceless
// llvmpipe), with no fixed-function state and no glGetTexImage at all, the
// fed program draws the same picture as the compatibility one on the
// desktop.
TEST(BuiltinFeed, OnOpenGlEsTheFedProgramDrawsTheDesktopsPicture) {
    Rendered compat = renderWith("osmesa", "compat");
    Rendered es = renderWith("egl-gles", "es");
    ASSERT_TRUE(compat.ok) << compat.error;
    ASSERT_TRUE(es.ok) << es.error;
    EXPECT_GT(litPixels(es.screen), 96 * 96 / 10);
    Difference d = compareRgb(compat.screen, es.screen);
    EXPECT_LE(d.maxSteps, 1) << d.maxSteps << " steps at (" << d.x << ", " << d.y << "), " << d.pixelsOver1
                             << " pixels differ by more than 1";
}

// glimmer_Color is the script's Color for the whole draw (a constant
// attribute, as glColor was): each object in its own colour.
TEST(BuiltinFeed, TheColourIsOneValueForTheWholeDraw) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE("backend " + backend);
        Rendered fed = renderWith(backend, "es");
        ASSERT_TRUE(fed.ok) << fed.error;
        // The sphere's centre, lit from the upper right: orange (r > g > b);
        // the torus, lower right: blue-cyan (b > r).
        auto px = [&](int x, int y) { return &fed.screen.u8[(size_t(y) * 96 + x) * 4]; };
        const unsigned char* sphere = px(30, 40);
        EXPECT_GT(sphere[0], sphere[1]);
        EXPECT_GT(sphere[1], sphere[2]);
        bool blueSeen = false;
        for (int y = 55; y < 80 && !blueSeen; ++y)
            for (int x = 60; x < 90 && !blueSeen; ++x)
                blueSeen = px(x, y)[2] > px(x, y)[0] + 60;
        EXPECT_TRUE(blueSeen);
    }
}

}  // namespace
