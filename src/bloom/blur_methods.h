// The blur methods `glimmer tradeoff` compares. Each is a GLIB script that
// Glimmer runs like any other (one renderer serves every front end), plus
// the double-precision CPU reference of the same kernel from src/reference.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "reference/blur_reference.h"

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

// Shader files the scripts name, by file name: tradeoff writes them beside
// the scripts it generates.
const std::map<std::string, std::string>& blurShaders();

// The methods, by family, each at a few strengths.
std::vector<BlurMethod> blurMethods();

// The standard deviation of a blur, from the second moment of its CPU
// reference's response to one bright texel: the Gaussian it is measured
// against for model error has this sigma.
double impulseSigma(const std::function<RgbImage(const RgbImage&)>& reference);

}  // namespace glimmer
