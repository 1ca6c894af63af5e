#include "bloom/blur_methods.h"

#include <cmath>

#include <fmt/format.h>

namespace glimmer {
namespace {

// Every method is a GLIB script over the kernel files of scripts/bloom (the
// same files the bloom lab's scripts use; see blurKernelDirs). Every pass
// draws one quad over its whole target with quad.vert; the fragment's vST is
// the target texel's centre, and offsets are in SOURCE texels (the
// conventions of src/reference/blur_reference.h).
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

std::string kawase(const std::string& image, int w, int h, const std::string& format, int iterations) {
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
        s += fmt::format("RenderToTexture {}\nProgram D{} ImageUnit {} uOffset 1\nQuadXY 0 1\n", 11 + k, k, src);
        src = 11 + k;
    }
    s += "Fragment kawase_up.frag\n";
    for (int k = iterations - 1; k >= 0; --k) {
        int dst = k == 0 ? 10 : 20 + k;
        s += fmt::format("RenderToTexture {}\nProgram U{} ImageUnit {} uOffset 1\nQuadXY 0 1\n", dst, k, src);
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

}  // namespace

std::vector<std::string> blurKernelDirs(const std::string& dataDir) {
    // superblur.frag is the seed's own file (shaders/); the others are scripts/bloom's.
    return {dataDir + "/scripts/bloom", dataDir + "/shaders"};
}

std::vector<BlurMethod> blurMethods() {
    std::vector<BlurMethod> out;
    for (int half : {1, 5, 11}) {
        BlurMethod m;
        int side = 2 * (half | 1) + 1;
        m.name = fmt::format("superblur h{}", half);
        m.family = "brute force (seed superblur)";
        m.tapsPerPixel = side * side;
        m.passes = 1;
        m.texelsWrittenPerPixel = 1;
        m.script = [half](const std::string& i, int w, int h, const std::string& f) { return superblur(i, w, h, f, half); };
        m.reference = [half](const RgbImage& img) { return superblurReference(img, half); };
        out.push_back(m);
    }
    // The LearnOpenGL kernel, as published (9 fetches a pass) and with
    // bilinear tap merging (5): one CPU reference serves both, so the
    // merged version's numerical error includes what merging costs on a GPU.
    struct Separable {
        const char* name;
        const char* family;
        const char* frag;
        int tapsPerPass;
    };
    for (const Separable& k : {Separable{"sep9", "separable 9-tap (LearnOpenGL)", "gauss9.frag", 9},
                               Separable{"linear5", "linear-sampled 9-tap", "linear5.frag", 5}}) {
        for (int pairs : {1, 2, 4}) {
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
            m.reference = [pairs](const RgbImage& img) {
                return separableBlur(img, learnOpenGLWeights(), pairs, Wrap::Repeat);
            };
            out.push_back(m);
        }
    }
    for (int it : {2, 3, 4}) {
        BlurMethod m;
        m.name = fmt::format("kawase x{}", it);
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
        m.script = [it](const std::string& i, int w, int h, const std::string& f) { return kawase(i, w, h, f, it); };
        m.reference = [it](const RgbImage& img) { return dualKawaseBlur(img, it, 1.0, Wrap::Repeat); };
        out.push_back(m);
    }
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

}  // namespace glimmer
