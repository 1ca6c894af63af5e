#include "bloom/blur_methods.h"

#include <cmath>

#include <fmt/format.h>

namespace glimmer {
namespace {

// Every method is a GLIB script over the kernel files of scripts/bloom (the
// same files the bloom lab's scripts use; see blurKernelDirs). Every pass
// draws one quad over its whole target with quad.vert; the fragment's vST is
// the target texel's centre, and offsets are in SOURCE texels (the
// conventions of src/bloom/blur_reference.h).
std::string header(const std::string& image, const std::string& format, int w, int h) {
    return fmt::format("##OpenGL GLIB\nOrtho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nTexture2D 5 {}\n"
                       "Texture2D 10 {} {} {}\nTexture2D 11 {} {} {}\nVertex quad.vert\n",
                       image, w, h, format, w, h, format);
}

// N horizontal+vertical pairs ping-ponging 10 <-> 11, ending on 10.
std::string separable(const std::string& frag, const std::string& image, int w, int h, const std::string& format,
                      int pairs) {
    std::string s = header(image, format, w, h) + "Fragment " + frag + "\n";
    int src = 5;
    for (int p = 0; p < pairs; ++p) {
        s += fmt::format("RenderToTexture 11\nProgram H{} ImageUnit {} uHorizontal 1\nQuadXY 0 1\n", p, src);
        s += fmt::format("RenderToTexture 10\nProgram V{} ImageUnit 11 uHorizontal 0\nQuadXY 0 1\n", p);
        src = 10;
    }
    return s + "RenderToTexture\n";
}

std::string kawase(const std::string& image, int w, int h, const std::string& format, int iterations, double offset) {
    std::string s = header(image, format, w, h);
    // Down to units 12, 13, ...; up again through 12 + k, ending in 10.
    std::vector<std::pair<int, int>> sizes = {{w, h}};
    for (int k = 0; k < iterations; ++k)
        sizes.push_back({std::max(1, sizes.back().first / 2), std::max(1, sizes.back().second / 2)});
    for (int k = 1; k <= iterations; ++k)
        s += fmt::format("Texture2D {} {} {} {}\n", 11 + k, sizes[size_t(k)].first, sizes[size_t(k)].second, format);
    for (int k = 1; k < iterations; ++k)  // the up chain's own targets
        s += fmt::format("Texture2D {} {} {} {}\n", 20 + k, sizes[size_t(k)].first, sizes[size_t(k)].second, format);
    s += "Fragment kawase_down.frag\n";
    int src = 5;
    for (int k = 1; k <= iterations; ++k) {
        s += fmt::format("RenderToTexture {}\nProgram D{} ImageUnit {} uOffset {}\nQuadXY 0 1\n", 11 + k, k, src, offset);
        src = 11 + k;
    }
    s += "Fragment kawase_up.frag\n";
    for (int k = iterations - 1; k >= 0; --k) {
        int dst = k == 0 ? 10 : 20 + k;
        s += fmt::format("RenderToTexture {}\nProgram U{} ImageUnit {} uOffset {}\nQuadXY 0 1\n", dst, k, src, offset);
        src = dst;
    }
    return s + "RenderToTexture\n";
}

std::string superblur(const std::string& image, int w, int h, const std::string& format, int half) {
    return header(image, format, w, h) +
           fmt::format("Fragment superblur.frag\nRenderToTexture 10\nProgram SuperBlur uHalfSize <0 {} 11> ImageUnit 5\n"
                       "QuadXY 0 1\nRenderToTexture\n",
                       half);
}

BlurMethod superblurMethod(int half) {
    BlurMethod m;
    int side = 2 * (half | 1) + 1;
    m.name = fmt::format("superblur h{}", half);
    m.family = "brute force (seed superblur)";
    m.tapsPerPixel = side * side;
    m.passes = 1;
    m.texelsWrittenPerPixel = 1;
    m.script = [half](const std::string& i, int w, int h, const std::string& f) { return superblur(i, w, h, f, half); };
    m.reference = [half](const RgbImage& img) { return superblurReference(img, half); };
    return m;
}

// The LearnOpenGL kernel, as published (9 fetches a pass) and with bilinear
// tap merging (5): one CPU reference serves both, so the merged version's
// numerical error includes what merging costs on a GPU.
struct Separable {
    const char* name;
    const char* family;
    const char* frag;
    int tapsPerPass;
};
const Separable kSeparables[] = {{"sep9", "separable 9-tap (LearnOpenGL)", "gauss9.frag", 9},
                                 {"linear5", "linear-sampled 9-tap", "linear5.frag", 5}};

BlurMethod separableMethod(const Separable& k, int pairs) {
    BlurMethod m;
    m.name = fmt::format("{} x{}", k.name, pairs);
    m.family = k.family;
    m.tapsPerPixel = 2 * k.tapsPerPass * pairs;
    m.passes = 2 * pairs;
    m.texelsWrittenPerPixel = 2.0 * pairs;
    std::string frag = k.frag;
    m.script = [pairs, frag](const std::string& i, int w, int h, const std::string& f) {
        return separable(frag, i, w, h, f, pairs);
    };
    m.reference = [pairs](const RgbImage& img) { return separableBlur(img, learnOpenGLWeights(), pairs, Wrap::Repeat); };
    return m;
}

// offset 1 is the published kernel; the name says any other.
BlurMethod kawaseMethod(int it, double offset) {
    BlurMethod m;
    m.name = offset == 1.0 ? fmt::format("kawase x{}", it) : fmt::format("kawase x{} o{:g}", it, offset);
    m.family = "dual Kawase (Bjorge 2015)";
    m.passes = 2 * it;
    // Down passes read 5 taps per output texel, up passes 8, each at a
    // quarter of the texels of the level above.
    double taps = 0, written = 0;
    for (int k = 1; k <= it; ++k) {
        taps += 5.0 / std::pow(4.0, k);
        written += 1.0 / std::pow(4.0, k);
    }
    for (int k = 0; k < it; ++k) {
        taps += 8.0 / std::pow(4.0, k);
        written += 1.0 / std::pow(4.0, k);
    }
    m.tapsPerPixel = int(std::lround(taps));
    m.texelsWrittenPerPixel = written;
    m.script = [it, offset](const std::string& i, int w, int h, const std::string& f) {
        return kawase(i, w, h, f, it, offset);
    };
    m.reference = [it, offset](const RgbImage& img) { return dualKawaseBlur(img, it, offset, Wrap::Repeat); };
    return m;
}

// Of the candidates, the one whose impulse sigma is nearest the target.
BlurMethod nearest(const std::vector<BlurMethod>& candidates, double target) {
    const BlurMethod* best = nullptr;
    double bestDiff = 0;
    for (const auto& m : candidates) {
        const double d = std::fabs(impulseSigma(m.reference) - target);
        if (!best || d < bestDiff) best = &m, bestDiff = d;
    }
    return *best;
}

}  // namespace

std::vector<std::string> blurKernelDirs(const std::string& dataDir) {
    // superblur.frag is the seed's own file (shaders/); the others are scripts/bloom's.
    return {dataDir + "/scripts/bloom", dataDir + "/shaders"};
}

std::vector<BlurMethod> blurMethods() {
    std::vector<BlurMethod> out;
    for (int half : {1, 5, 11}) out.push_back(superblurMethod(half));
    for (const Separable& k : kSeparables)
        for (int pairs : {1, 2, 4}) out.push_back(separableMethod(k, pairs));
    for (int it : {2, 3, 4}) out.push_back(kawaseMethod(it, 1.0));
    return out;
}

std::vector<BlurMethod> blurMethodsMatched(double sigma) {
    std::vector<BlurMethod> out;
    // superblur: sigma grows about half a texel per step of uHalfSize
    // (h5: 2.75, h11: 5.71); try the steps around that estimate.
    std::vector<BlurMethod> c;
    const int guess = std::max(1, int(std::lround(2 * sigma)));
    for (int half = std::max(1, guess - 3); half <= std::min(kMatchMaxHalfSize, guess + 3); ++half)
        c.push_back(superblurMethod(half));
    if (c.empty()) c.push_back(superblurMethod(kMatchMaxHalfSize));
    out.push_back(nearest(c, sigma));
    // Separable pairs: variances add, so N pairs have sigma1 * sqrt(N).
    for (const Separable& k : kSeparables) {
        const double sigma1 = impulseSigma(separableMethod(k, 1).reference);
        const int pairs = std::clamp(int(std::lround(sigma * sigma / (sigma1 * sigma1))), 1, kMatchMaxPairs);
        c.clear();
        for (int p = std::max(1, pairs - 1); p <= std::min(kMatchMaxPairs, pairs + 1); ++p)
            c.push_back(separableMethod(k, p));
        out.push_back(nearest(c, sigma));
    }
    // Dual Kawase: the iteration count whose published kernel (offset 1) is
    // nearest the target on a log scale, then the offset (0.5 to 2.5 in
    // steps of 1/8) that fine-tunes it. Fewer iterations with a large offset
    // could reach the same sigma, but their taps spread apart and the blur
    // shows holes, which is not how the method is used.
    int bestIt = 1;
    double bestRatio = 0;
    for (int it = 1; it <= 5; ++it) {
        const double r = std::fabs(std::log(impulseSigma(kawaseMethod(it, 1.0).reference) / sigma));
        if (it == 1 || r < bestRatio) bestIt = it, bestRatio = r;
    }
    c.clear();
    for (int q = 4; q <= 20; ++q) c.push_back(kawaseMethod(bestIt, q * 0.125));
    out.push_back(nearest(c, sigma));
    return out;
}

double impulseSigma(const std::function<RgbImage(const RgbImage&)>& reference) {
    const int n = 128;
    RgbImage dot(n, n, 0.0);
    dot.set(n / 2, n / 2, 1.0);
    RgbImage r = reference(dot);
    double sum = 0, m2 = 0;
    // The dot sits at texel n/2; distances are measured from there, wrapping
    // as the blur did.
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            double v = r.at(x, y, 0);
            double dx = x - n / 2, dy = y - n / 2;
            sum += v;
            m2 += v * (dx * dx + dy * dy) / 2.0;  // per axis
        }
    return sum > 0 ? std::sqrt(m2 / sum) : 0.0;
}

std::vector<BlurMethod> methodsNamed(const std::vector<BlurMethod>& all, const std::vector<std::string>& words) {
    std::vector<BlurMethod> out;
    for (const BlurMethod& m : all) {
        bool keep = words.empty();
        for (const auto& w : words) keep |= m.name.find(w) != std::string::npos;
        if (keep) out.push_back(m);
    }
    return out;
}

}  // namespace glimmer
