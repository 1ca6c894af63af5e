// The blur methods `glimmer tradeoff` compares, one row each: a name, its
// family, its cost (taps, passes, texels written), a GLIB script over the
// kernel files of scripts/bloom that Glimmer runs like any other (one
// renderer serves every front end), and the double-precision CPU reference of
// the same kernel from src/reference. A new method is a kernel file there
// plus a row in blurMethods().
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "bloom/blur_reference.h"

namespace glimmer {

struct BlurMethod {
    std::string name;     // "sep9 x2"
    std::string family;   // "separable 9-tap (LearnOpenGL)"
    int tapsPerPixel = 0; // texture fetches per output pixel, all passes, at full size
    int passes = 0;
    double texelsWrittenPerPixel = 0;  // target texels written per input texel (chains write less)
    // The script, given the input image, its size and the target format.
    std::function<std::string(const std::string& image, int w, int h, const std::string& format)> script;
    int outputUnit = 10;  // the unit whose texture holds the blurred picture
    std::function<RgbImage(const RgbImage&)> reference;
};

// The folders the methods' scripts find their kernel files in (as -I
// folders), given Glimmer's data folder (process/data_dir.h).
std::vector<std::string> blurKernelDirs(const std::string& dataDir);

// The methods, by family, each at a few strengths.
std::vector<BlurMethod> blurMethods();

// The methods of `all` whose name holds one of `words` ("sep9", "h11");
// every one when `words` is empty (tradeoff's --methods, the page's list).
std::vector<BlurMethod> methodsNamed(const std::vector<BlurMethod>& all, const std::vector<std::string>& words);

// One method of each family (superblur, sep9, linear5, dual Kawase) with the
// parameter that brings its impulse sigma nearest `sigma`: uHalfSize for
// superblur (at most kMatchMaxHalfSize), the number of horizontal+vertical
// pairs for the separable kernels (at most kMatchMaxPairs: sigma grows as the
// square root of the passes), for dual Kawase the iteration count whose
// published kernel comes nearest, then its tap offset (0.5 to 2.5, steps of
// 1/8). Integer parameters cannot hit every sigma: impulseSigma of each
// says how close it came, and callers report that, not the target.
constexpr int kMatchMaxHalfSize = 40, kMatchMaxPairs = 32;
std::vector<BlurMethod> blurMethodsMatched(double sigma);

// The standard deviation of a blur, from the second moment of its CPU
// reference's response to one bright texel: the Gaussian it is measured
// against for model error has this sigma.
double impulseSigma(const std::function<RgbImage(const RgbImage&)>& reference);

}  // namespace glimmer
