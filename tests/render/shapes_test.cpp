// scripts/shapes.glib: a sphere, torus, box and subdivided quad under a
// perspective camera, lit by their normals. Checks what a broken matrix,
// depth or normal path would change.
#include <gtest/gtest.h>

#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

const std::uint8_t* pixel(const Image& img, int x, int y) {
    return &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
}

TEST(Shapes, BackgroundAndLitSphereWhereTheyBelong) {
    PlanOptions options;
    options.width = options.height = 200;
    Rendered r = renderScript(testBackends().front(), std::string(GLIMMER_SOURCE_DIR) + "/scripts/shapes.glib", {},
                              {}, options);
    ASSERT_TRUE(r.ok) << r.error;
    // Background 0.1 0.1 0.15 in a corner: 0.1 * 255 = 25.5 rounds to 26 (or 25).
    const std::uint8_t* corner = pixel(r.screen, 2, 2);
    EXPECT_NEAR(corner[0], 26, 1);
    EXPECT_NEAR(corner[2], 38, 1);

    // The sphere sits at (-1.7, 1.3, 0), 8 units in front of a 50-degree
    // camera: its centre projects to x = 0.5 + 0.5 * (-1.7 / (8 tan 25)),
    // y (from the top) = 0.5 - 0.5 * (1.3 / (8 tan 25)).
    const double k = 0.5 / (8.0 * std::tan(25.0 * 3.14159265358979 / 180.0));
    int sx = int(200 * (0.5 - 1.7 * k)), sy = int(200 * (0.5 - 1.3 * k));
    const std::uint8_t* sphere = pixel(r.screen, sx, sy);
    // Lit orange: red strongest, blue weakest, and brighter than ambient
    // alone (the normal there faces the camera, half towards the light).
    EXPECT_GT(sphere[0], sphere[1]);
    EXPECT_GT(sphere[1], sphere[2]);
    EXPECT_GT(sphere[0], 120);

    // Between the shapes there is only background.
    const std::uint8_t* middle = pixel(r.screen, 100, 100);
    EXPECT_NEAR(middle[0], 26, 1);
}

}  // namespace
