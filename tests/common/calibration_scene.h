// The superblur + bloom calibration scene for the front ends (render,
// sheet, view): the same passes as tests/render/superblur_reference_test.cpp,
// but the bloom is drawn to the screen, so each front end's own output can be
// checked against the double-precision CPU reference (src/reference) rather
// than against another front end.
//
// Every quad covers its target exactly (Ortho -1 1 -1 1, QuadXY 0 1, output
// the size of the input), so each superblur tap lands on a texel centre. On
// the 80x48 screen glman's Ortho widens x to +-80/48 to keep squares square,
// so the screen's quad is scaled by 80/48 along x to fill it.
#pragma once
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>

#include "image/image.h"
#include "image/test_images.h"
#include "bloom/superblur_reference.h"

namespace glimmer::calibration {

// Not a power of two and not square, so a swapped axis or an off-by-one
// texel shows.
constexpr int kW = 80, kH = 48;

// Writes input.bmp (noise) and calibration.glib into `dir`; returns the
// script's path. Shaders come from the repository's shaders/ (pass -I).
inline std::filesystem::path writeScene(const std::filesystem::path& dir, std::string& error) {
    std::filesystem::create_directories(dir);
    if (!writeBmp((dir / "input.bmp").string(), makeNoiseImage(kW, kH, 7), error)) return {};
    std::ofstream(dir / "calibration.glib") << "##OpenGL GLIB\n"
                                               "WindowSize " << kW << " " << kH << "\n"
                                               "Ortho -1 1 -1 1\n"
                                               "LookAt 0 0 1  0 0 0  0 1 0\n"
                                               "Texture2D 5 input.bmp\n"
                                               "Texture2D 6 " << kW << " " << kH << "\n"
                                               "RenderToTexture 6\n"
                                               "Clear\n"
                                               "Vertex superblur.vert\n"
                                               "Fragment superblur.frag\n"
                                               "Program SuperBlur  uHalfSize <0 0 11>  ImageUnit 5\n"
                                               "QuadXY 0 1\n"
                                               "RenderToTexture\n"
                                               "Clear\n"
                                               "Vertex bloom.vert\n"
                                               "Fragment bloom.frag\n"
                                               "Program Bloom  BlurUnit 6  ImageUnit 5  uAdd <0. 0. 4.>\n"
                                               "Scale " << std::setprecision(10) << double(kW) / double(kH) << " 1 1\n"
                                               "QuadXY 0 1\n";
    return dir / "calibration.glib";
}

inline std::string shaderDir() { return std::string(GLIMMER_SOURCE_DIR) + "/shaders"; }

// The input as the scene's BMP holds it.
inline RgbImage input(const std::filesystem::path& dir) {
    Image img;
    std::string why;
    loadImage((dir / "input.bmp").string(), img, why);
    return toRgb(img);
}

// The screen the scene should show, all in double precision from the input
// alone, rounded to RGBA8. A renderer may differ from it by at most 1 + uAdd
// steps (whole uAdd): the blur target holds the exact blur within 1 step
// (exclusive) whichever way it rounds, uAdd multiplies that, the screen's own
// rounding adds under 1 and this rounding under 0.5; the difference is an
// integer below 1.5 + uAdd. See tests/render/superblur_reference_test.cpp.
inline Image expectedScreen(const RgbImage& in, int halfSize, double add) {
    return quantizeToRgba8(bloomReference(in, superblurReference(in, halfSize), add));
}

// The largest RGB difference in 8-bit steps between `got` and `want`, over
// the w x h rectangle of `got` at (x0, y0) against all of `want`; 256 when
// the rectangle does not fit. `where` tells the first worst pixel.
inline int maxStepsIn(const Image& got, int x0, int y0, const Image& want, std::string* where = nullptr) {
    if (x0 < 0 || y0 < 0 || x0 + want.width > got.width || y0 + want.height > got.height) return 256;
    int worst = 0;
    for (int y = 0; y < want.height; ++y)
        for (int x = 0; x < want.width; ++x)
            for (int c = 0; c < 3; ++c) {
                int a = got.u8[(size_t(y0 + y) * size_t(got.width) + size_t(x0 + x)) * 4 + size_t(c)];
                int b = want.u8[(size_t(y) * size_t(want.width) + size_t(x)) * 4 + size_t(c)];
                int d = a > b ? a - b : b - a;
                if (d > worst) {
                    worst = d;
                    if (where) *where = "(" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                                        std::to_string(c) + ": " + std::to_string(a) + " for " + std::to_string(b);
                }
            }
    return worst;
}

}  // namespace glimmer::calibration
