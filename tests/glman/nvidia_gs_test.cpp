// Geometry shaders written for NVIDIA's GL_EXT_geometry_shader4
// (gl_PositionIn[], gl_VerticesIn, gl_FrontColorIn[], gl_TexCoordIn[][],
// varying out, no input layout) render on Mesa after translation, on OSMesa
// and EGL surfaceless, checked by pixels worked out by hand. The scripts and
// shaders are in tests/data/nvidia.
#include <cmath>

#include <gtest/gtest.h>

#include "glman_harness.h"

using namespace glimmer;
using namespace glimmer::glmantest;

namespace {

std::string nvidia(const std::string& name) { return std::string(GLIMMER_TEST_DATA) + "/nvidia/" + name + ".glib"; }

// The pixel under world point (x, y) of a 96 x 96 picture with Ortho -2 2 -2 2.
std::array<int, 3> at(const Image& img, double x, double y) {
    int col = int(std::floor((x + 2.) / 4. * 96.)), row = int(std::floor((2. - y) / 4. * 96.));
    const std::uint8_t* p = pixel(img, col, row);
    return {p[0], p[1], p[2]};
}
const std::array<int, 3> kBlack{0, 0, 0};

// Each case runs on every backend testBackends() names, read when the test
// runs: instantiating over that list fixed the cases at build time, so a
// GLIMMER_TEST_BACKENDS set later turned the listed cases into "Running 0
// tests" (issue 18: no outcome may depend on the environment of the build).
template <typename Body>
void onEveryBackend(Body body) {
    for (const std::string& backend : glimmer::testing::testBackends()) {
        SCOPED_TRACE("backend " + backend);
        body(backend);
    }
}

TEST(NvidiaGs, SilhouetteOfAnOctahedronOnObjAdj) {
    onEveryBackend([](const std::string& backend) {
        auto r = glimmer::testing::renderScript(backend, nvidia("silhouette"), {}, {});
        ASSERT_TRUE(r.ok) << r.error;
        // Scale 1.5 seen down -Z: the outline is the diamond |x| + |y| = 1.5.
        const std::array<int, 3> yellow{255, 255, 0};
        EXPECT_EQ(at(r.screen, .75, .75), yellow);
        EXPECT_EQ(at(r.screen, -.75, .75), yellow);
        EXPECT_EQ(at(r.screen, -.75, -.75), yellow);
        EXPECT_EQ(at(r.screen, .75, -.75), yellow);
        // The edges inside the outline (along the axes) are not silhouettes.
        EXPECT_EQ(at(r.screen, .75, 0.), kBlack);
        EXPECT_EQ(at(r.screen, 0., -.75), kBlack);
        EXPECT_EQ(at(r.screen, .3, .3), kBlack);
        EXPECT_EQ(at(r.screen, 1.2, 1.2), kBlack);
    });
}

TEST(NvidiaGs, SubdividedOctahedronIsADiskOnTriangles) {
    onEveryBackend([](const std::string& backend) {
        auto r = glimmer::testing::renderScript(backend, nvidia("subdivide"), {}, {});
        ASSERT_TRUE(r.ok) << r.error;
        const std::array<int, 3> blue{0, 128, 255};
        // Radius 1.5 at 45 degrees: inside the disk, far outside the unsubdivided
        // diamond |x| + |y| = 1.5.
        double in = 1.44 / std::sqrt(2.), out = 1.56 / std::sqrt(2.);
        EXPECT_EQ(at(r.screen, in, in), blue);
        EXPECT_EQ(at(r.screen, -in, -in), blue);
        EXPECT_EQ(at(r.screen, 0., 1.44), blue);
        EXPECT_EQ(at(r.screen, out, out), kBlack);
        EXPECT_EQ(at(r.screen, 0., -1.56), kBlack);
        // Level 0 is the octahedron itself: the diamond.
        auto flat = glimmer::testing::renderScript(backend, nvidia("subdivide"), {"uLevel=0"}, {});
        ASSERT_TRUE(flat.ok) << flat.error;
        EXPECT_EQ(at(flat.screen, in, in), kBlack);
        EXPECT_EQ(at(flat.screen, .7, .7), blue);
    });
}

TEST(NvidiaGs, BezierCurveOnLinesAdjacency) {
    onEveryBackend([](const std::string& backend) {
        auto r = glimmer::testing::renderScript(backend, nvidia("bezier"), {}, {});
        ASSERT_TRUE(r.ok) << r.error;
        const std::array<int, 3> green{0, 255, 0};
        // B(t) of P0 (-1.5,-1.5) P1 (-1.5,1.5) P2 (1.5,1.5) P3 (1.5,-1.5).
        auto bezier = [](double t, double a, double b, double c, double d) {
            double s = 1. - t;
            return s * s * s * a + 3. * s * s * t * b + 3. * s * t * t * c + t * t * t * d;
        };
        // Mid-segment (64 segments): a wide line leaves a pixel out at the joins.
        for (double t : {16.5 / 64., 40.5 / 64., 47.5 / 64.})
            EXPECT_EQ(at(r.screen, bezier(t, -1.5, -1.5, 1.5, 1.5), bezier(t, -1.5, 1.5, 1.5, -1.5)), green) << t;
        EXPECT_EQ(at(r.screen, 0., .75), green);  // B(.5) by hand
        // Not the control polygon: its top edge at y = 1.5, its sides at x = -1.5.
        EXPECT_EQ(at(r.screen, 0., 1.5), kBlack);
        EXPECT_EQ(at(r.screen, -1.5, 0.), kBlack);
        EXPECT_EQ(at(r.screen, 0., 0.), kBlack);
    });
}

TEST(NvidiaGs, ShrunkObjTrianglesKeepTheirTexCoords) {
    onEveryBackend([](const std::string& backend) {
        auto r = glimmer::testing::renderScript(backend, nvidia("shrink"), {}, {});
        ASSERT_TRUE(r.ok) << r.error;
        // Lower-right triangle (-1.5,-1.5) (1.5,-1.5) (1.5,1.5), st (0,0) (1,0) (1,1):
        // its centre (0.5,-0.5) keeps st (2/3, 1/3), and shrunk to half, st
        // changes twice as fast: s = 2/3 + 2 (x - .5) / 3, t = 1/3 + 2 (y + .5) / 3.
        // Colour (s, t, 1), read at the pixel's centre.
        auto centre = [](double x) { return (std::floor((x + 2.) / 4. * 96.) + .5) / 96. * 4. - 2.; };
        auto c = at(r.screen, .5, -.5);
        double x = centre(.5), y = -centre(.5);
        EXPECT_NEAR(c[0], 255. * (2. / 3. + 2. * (x - .5) / 3.), 1.);
        EXPECT_NEAR(c[1], 255. * (1. / 3. + 2. * (y + .5) / 3.), 1.);
        EXPECT_EQ(c[2], 255);
        c = at(r.screen, -.5, .5);  // the other, st (0,0) (1,1) (0,1): centre st (1/3, 2/3)
        x = centre(-.5), y = -centre(-.5);
        EXPECT_NEAR(c[0], 255. * (1. / 3. + 2. * (x + .5) / 3.), 1.);
        EXPECT_NEAR(c[1], 255. * (2. / 3. + 2. * (y - .5) / 3.), 1.);
        // Half size: the diagonal between them and the corners are empty.
        EXPECT_EQ(at(r.screen, 0., 0.), kBlack);
        EXPECT_EQ(at(r.screen, -1.4, -1.4), kBlack);
        EXPECT_EQ(at(r.screen, 1.4, 1.4), kBlack);
        // At full size they cover the square.
        auto full = glimmer::testing::renderScript(backend, nvidia("shrink"), {"uShrink=1"}, {});
        ASSERT_TRUE(full.ok) << full.error;
        EXPECT_NE(at(full.screen, -1.4, -1.4), kBlack);
        EXPECT_NE(at(full.screen, .1, .05), kBlack);
    });
}


// One warning per shader says what was translated, on the shader's line of
// its first EXT form; nothing else is said.
TEST(NvidiaGsCheck, TranslationIsAnnouncedOncePerShader) {
    auto r = runPipeline(nvidia("silhouette"), true, false);
    ASSERT_TRUE(r->prepared) << r->printed();
    ASSERT_EQ(r->diags.all().size(), 1u) << r->printed();
    const Diagnostic& d = r->diags.all()[0];
    EXPECT_EQ(d.severity, Severity::Warning);
    EXPECT_EQ(std::filesystem::path(d.file).filename(), "silhouette.geom");
    EXPECT_EQ(d.loc.line, 3);
    EXPECT_EQ(d.message, "GL_EXT_geometry_shader4 shader (NVIDIA) translated to standard GLSL: #extension "
                         "GL_EXT_geometry_shader4 dropped, gl_PositionIn[i] -> gl_in[i].gl_Position, "
                         "gl_FrontColorIn[i] -> gl_in[i].gl_FrontColor");
}

TEST(NvidiaGsCheck, AMissingInputLayoutIsTakenFromTheDraw) {
    auto r = runPipeline(nvidia("subdivide"), true, false);
    ASSERT_TRUE(r->prepared) << r->printed();
    // The translation's note, then Mesa's four "used uninitialized" about
    // the globals main sets before Put runs, on every run (the driver's disk
    // cache is off, backends/driver_shader_cache.h): false alarms, each a
    // note that says so (issue 19), naming the line of main that sets it.
    ASSERT_EQ(r->diags.all().size(), 5u) << r->printed();
    const char* globals[] = {"P0", "E1", "E2", "N"};
    for (int k = 0; k < 4; ++k) {
        const Diagnostic& d = r->diags.all()[1 + size_t(k)];
        EXPECT_EQ(d.loc.line, 16);
        EXPECT_EQ(d.severity, Severity::Note);
        EXPECT_EQ(d.message, std::string("the driver's warning \"`") + globals[k] +
                                 "' used uninitialized\" is a false alarm: main sets the global " + globals[k] +
                                 " (line " + std::to_string(24 + k) + ") before it calls any function");
    }
    EXPECT_EQ(r->diags.all()[0].loc.line, 3);
    EXPECT_EQ(r->diags.all()[0].message,
              "GL_EXT_geometry_shader4 shader (NVIDIA) translated to standard GLSL: #extension "
              "GL_EXT_geometry_shader4 dropped, gl_FrontColorIn[i] -> gl_in[i].gl_FrontColor, gl_PositionIn[i] -> "
              "gl_in[i].gl_Position; layout(triangles) in; added from the draw on line 11 of subdivide.glib");
}

// A real mistake in a translated shader is reported on the user's own line.
TEST(NvidiaGsCheck, ErrorsInATranslatedShaderKeepTheirLines) {
    auto r = runPipeline(nvidia("broken"), true, false);
    ASSERT_TRUE(r->renderer) << r->printed();
    EXPECT_FALSE(r->prepared);
    std::vector<std::pair<int, std::string>> errors;
    for (const auto& d : r->diags.all())
        if (d.severity == Severity::Error) {
            EXPECT_EQ(std::filesystem::path(d.file).filename(), "broken.geom") << d.message;
            errors.push_back({d.loc.line, d.message});
        }
    // Mesa: "`uScale' undeclared", then "operands to arithmetic operators must be numeric".
    ASSERT_EQ(errors.size(), 2u) << r->printed();
    EXPECT_EQ(errors[0].first, 9);
    EXPECT_EQ(errors[0].second, "`uScale' undeclared");
    EXPECT_EQ(errors[1].first, 9);
}

// ES precision qualifiers in GLSL 1.20, which NVIDIA takes and Mesa refuses
// ("illegal use of reserved word `precision'"): removed, announced once, and
// the shader draws.
TEST(NvidiaLeniency, PrecisionQualifiersBeforeGlsl130AreRemoved) {
    auto r = runPipeline(nvidia("precision"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    ASSERT_EQ(r->diags.all().size(), 1u) << r->printed();
    const Diagnostic& d = r->diags.all()[0];
    EXPECT_EQ(d.severity, Severity::Warning);
    EXPECT_EQ(std::filesystem::path(d.file).filename(), "precision.frag");
    EXPECT_EQ(d.loc.line, 4);
    EXPECT_EQ(d.message, "precision qualifiers (OpenGL ES; NVIDIA accepts them) removed: GLSL before 1.30 has none, "
                         "and on desktop OpenGL they change nothing");
    // vST runs 0..1 across the quad: red grows to the right.
    EXPECT_LT(pixel(r->screen, 2, 16)[0], 32);
    EXPECT_GT(pixel(r->screen, 29, 16)[0], 200);
}

}  // namespace
