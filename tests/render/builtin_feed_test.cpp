// The way WebGL 2 draws, checked on the desktop: a program that declares the
// built-ins' stand-ins (glimmer_Vertex, glimmer_NormalMatrix, ...:
// shader/compat_builtins.h) is fed them as attributes and uniforms
// (gl/builtin_feed.h), and draws the same pixels as its compatibility-profile
// twin fed by the fixed-function state: a lit, textured-coordinate sphere
// under a perspective, moved by the script's transforms, in a colour.
#include <fstream>

#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

// The scene, its two programs differing only in how they name the built-ins.
const char* kScript =
    "Perspective 60\nLookAt 0 0 4  0 0 0  0 1 0\nBackground .1 .1 .2\nClear\n"
    "Vertex lit.vert\nFragment lit.frag\nProgram Lit\n"
    "Color 1 .6 .2\nTranslate -.8 .2 0\nRotate 30  1 1 0\nSphere 1 40 30\n"
    "Color .2 .8 1\nTranslate 1.6 -.6 -.5\nScale .6\nTorus .3 .8 30 30\n";

const char* kCompatVertex = R"(#version 330 compatibility
out vec3 vN;
out vec3 vE;
out vec2 vST;
out vec4 vColor;
void main() {
    vN = normalize(gl_NormalMatrix * gl_Normal);
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vE = -eye.xyz;
    vST = gl_MultiTexCoord0.st;
    vColor = gl_Color;
    vec4 back = gl_ModelViewMatrixInverse * eye;           // == gl_Vertex
    gl_Position = gl_ProjectionMatrix * gl_ModelViewMatrix * back;
}
)";
const char* kCompatFragment = R"(#version 330 compatibility
in vec3 vN;
in vec3 vE;
in vec2 vST;
in vec4 vColor;
void main() {
    vec3 n = normalize(vN);
    float d = max(dot(n, normalize(vec3(1., 1., 1.))), 0.);
    float stripe = step(.5, fract(vST.s * 8.)) * .3;
    gl_FragColor = vec4(vColor.rgb * (.2 + .8 * d) + stripe, 1.);
}
)";
// The same two shaders as the translation writes them for WebGL 2.
const char* kFedVertex = R"(#version 300 es
uniform mat3 glimmer_NormalMatrix;
uniform mat4 glimmer_ModelViewMatrix;
uniform mat4 glimmer_ProjectionMatrix;
uniform mat4 glimmer_ModelViewMatrixInverse;
in vec4 glimmer_Vertex;
in vec3 glimmer_Normal;
in vec4 glimmer_MultiTexCoord0;
in vec4 glimmer_Color;
out vec3 vN;
out vec3 vE;
out vec2 vST;
out vec4 vColor;
void main() {
    vN = normalize(glimmer_NormalMatrix * glimmer_Normal);
    vec4 eye = glimmer_ModelViewMatrix * glimmer_Vertex;
    vE = -eye.xyz;
    vST = glimmer_MultiTexCoord0.st;
    vColor = glimmer_Color;
    vec4 back = glimmer_ModelViewMatrixInverse * eye;
    gl_Position = glimmer_ProjectionMatrix * glimmer_ModelViewMatrix * back;
}
)";
const char* kFedFragment = R"(#version 300 es
precision highp float;
in vec3 vN;
in vec3 vE;
in vec2 vST;
in vec4 vColor;
out vec4 fragColor;
void main() {
    vec3 n = normalize(vN);
    float d = max(dot(n, normalize(vec3(1., 1., 1.))), 0.);
    float stripe = step(.5, fract(vST.s * 8.)) * .3;
    fragColor = vec4(vColor.rgb * (.2 + .8 * d) + stripe, 1.);
}
)";

Rendered renderWith(const std::string& backend, const char* vert, const char* frag) {
    TestFolder dir("glimmer_builtin_feed_");
    std::ofstream(dir.path / "lit.vert") << vert;
    std::ofstream(dir.path / "lit.frag") << frag;
    std::ofstream(dir.path / "s.glib") << kScript;
    PlanOptions options;
    options.width = options.height = 96;
    return renderScript(backend, (dir.path / "s.glib").string(), {}, {}, options);
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
        Rendered compat = renderWith(backend, kCompatVertex, kCompatFragment);
        Rendered fed = renderWith(backend, kFedVertex, kFedFragment);
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
    Rendered compat = renderWith("osmesa", kCompatVertex, kCompatFragment);
    Rendered es = renderWith("egl-gles", kFedVertex, kFedFragment);
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
        Rendered fed = renderWith(backend, kFedVertex, kFedFragment);
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
