// `glimmer render` and `glimmer sheet` against the double-precision CPU
// reference of the superblur and bloom (src/reference), not against each
// other: a bug the whole pipeline shares (a uniform uploaded as 0, a blur
// that reads the wrong texel) fails here. Tolerances are derived in
// tests/common/calibration_scene.h and tests/render/superblur_reference_test.cpp.
#include <gtest/gtest.h>

#include "sheet/sheet_layout.h"
#include "common/calibration_scene.h"
#include "run_glimmer.h"

using namespace glimmer_cli;
namespace cal = glimmer::calibration;

namespace {

TEST(CliReference, RenderAndItsBlurDumpMatchTheCpuReference) {
    TempDir dir;
    std::string why;
    auto script = cal::writeScene(dir.path(), why);
    ASSERT_FALSE(script.empty()) << why;
    auto r = runGlimmer({"render", script.string(), "-I", cal::shaderDir(), "--set", "uHalfSize=3", "--set", "uAdd=2",
                         "--dump", "6=" + dir.file("blur.png"), "--backend", "osmesa", "-o", dir.file("out.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    glimmer::RgbImage in = cal::input(dir.path());
    glimmer::Image out = loadPicture(dir.file("out.png")), blur = loadPicture(dir.file("blur.png"));
    ASSERT_EQ(out.width, cal::kW);
    ASSERT_EQ(out.height, cal::kH);
    std::string where;
    // The dumped blur target: within 1 step of the exact blur, rounded.
    EXPECT_LE(cal::maxStepsIn(blur, 0, 0, glimmer::quantizeToRgba8(glimmer::superblurReference(in, 3)), &where), 1)
        << where;
    // The screen from the bytes the blur target holds: within 1 step.
    glimmer::Image fromStored = glimmer::quantizeToRgba8(glimmer::bloomReference(in, glimmer::toRgb(blur), 2.0));
    EXPECT_LE(cal::maxStepsIn(out, 0, 0, fromStored, &where), 1) << where;
    // And from the input alone: within 1 + uAdd = 3 steps.
    EXPECT_LE(cal::maxStepsIn(out, 0, 0, cal::expectedScreen(in, 3, 2.0), &where), 3) << where;
}

TEST(CliReference, SheetCellsMatchTheCpuReference) {
    TempDir dir;
    std::string why;
    auto script = cal::writeScene(dir.path(), why);
    ASSERT_FALSE(script.empty()) << why;
    auto r = runGlimmer({"sheet", script.string(), "-I", cal::shaderDir(), "--vary", "uAdd=0,1,4", "--vary",
                         "uHalfSize=1,5", "--size", std::to_string(cal::kW) + "x" + std::to_string(cal::kH),
                         "--backend", "osmesa", "-o", dir.file("sheet.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    glimmer::Image sheet = loadPicture(dir.file("sheet.png"));
    glimmer::RgbImage in = cal::input(dir.path());
    // Where the cells are: the sheet's own layout (tests/cli/sheet_test.cpp
    // finds them on the sheet independently).
    glimmer::SheetLayout layout = glimmer::layoutSheet(script.filename().string(), "uAdd", {"0", "1", "4"},
                                                       "uHalfSize", {"1", "5"}, cal::kW, cal::kH);
    ASSERT_EQ(sheet.width, layout.width);
    ASSERT_EQ(sheet.height, layout.height);
    const double adds[] = {0, 1, 4};
    const int halves[] = {1, 5};
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col) {
            auto [x0, y0] = layout.cellOrigin(col, row);
            std::string where;
            EXPECT_LE(cal::maxStepsIn(sheet, x0, y0, cal::expectedScreen(in, halves[row], adds[col]), &where),
                      1 + int(adds[col]))
                << "cell uAdd=" << adds[col] << " uHalfSize=" << halves[row] << " " << where;
        }
}

}  // namespace
