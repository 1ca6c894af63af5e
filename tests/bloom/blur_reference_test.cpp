// Measured properties of the double-precision blur references: each test
// computes a number and checks it against what the method promises.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bloom/blur_reference.h"

using namespace glimmer;

namespace {

// Deterministic values in [0, 1) (a 32-bit LCG), so failures reproduce.
RgbImage noise(int w, int h, std::uint32_t seed) {
    RgbImage img(w, h);
    for (double& v : img.rgb) {
        seed = seed * 1664525u + 1013904223u;
        v = double(seed >> 8) / double(1u << 24);
    }
    return img;
}

double maxAbsDiff(const RgbImage& a, const RgbImage& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    double m = 0;
    for (size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i) m = std::max(m, std::fabs(a.rgb[i] - b.rgb[i]));
    return m;
}

// Largest |value - c| over the image; NaN if any value is not finite.
double maxDeviation(const RgbImage& img, double c) {
    double m = 0;
    for (double v : img.rgb) {
        if (!std::isfinite(v)) return NAN;
        m = std::max(m, std::fabs(v - c));
    }
    return m;
}

bool allFinite(const RgbImage& img) {
    for (double v : img.rgb)
        if (!std::isfinite(v)) return false;
    return true;
}

double fullSum(const std::vector<double>& half) {
    double s = half.empty() ? 0 : half[0];
    for (size_t i = 1; i < half.size(); ++i) s += 2 * half[i];
    return s;
}

std::vector<double> normalised(std::vector<double> w) {
    const double s = fullSum(w);
    for (double& v : w) v /= s;
    return w;
}

// Centroid of channel 0 in texel coordinates (texel centres at i + 0.5).
void centroid(const RgbImage& img, double& cx, double& cy) {
    double sum = 0, sx = 0, sy = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double v = img.at(x, y, 0);
            sum += v, sx += v * (x + 0.5), sy += v * (y + 0.5);
        }
    cx = sx / sum, cy = sy / sum;
}

struct Method {
    std::string name;
    std::function<RgbImage(const RgbImage&, Wrap)> run;
};

// Every method that promises to preserve a constant (weights sum to 1).
std::vector<Method> normalisedMethods() {
    return {
        {"gaussianBlur", [](const RgbImage& i, Wrap w) { return gaussianBlur(i, 2.0, 6, w); }},
        {"separableBlur(normalised LearnOpenGL) x3",
         [](const RgbImage& i, Wrap w) { return separableBlur(i, normalised(learnOpenGLWeights()), 3, w); }},
        {"linearSampledBlur(gaussian)",
         [](const RgbImage& i, Wrap w) { return linearSampledBlur(i, linearSampledWeights(gaussianWeights(3, 9)), 2, w); }},
        {"solTrader", [](const RgbImage& i, Wrap w) { return linearSampledBlur(i, solTraderTaps(1.2), 1, w); }},
        {"downsample2x", [](const RgbImage& i, Wrap) { return downsample2x(i); }},
        {"upsampleBilinear", [](const RgbImage& i, Wrap w) { return upsampleBilinear(i, 2 * i.width + 1, 3 * i.height, w); }},
        {"codDownsample13", [](const RgbImage& i, Wrap w) { return codDownsample13(i, false, w); }},
        {"codDownsample13 Karis", [](const RgbImage& i, Wrap w) { return codDownsample13(i, true, w); }},
        {"codUpsampleTent", [](const RgbImage& i, Wrap w) { return codUpsampleTent(i, 2 * i.width, 2 * i.height, 1.0, w); }},
        {"codBloomChain", [](const RgbImage& i, Wrap w) { return codBloomChain(i, 4, 1.0, w); }},
        {"kawaseDown", [](const RgbImage& i, Wrap w) { return kawaseDown(i, 2.0, w); }},
        {"kawaseUp", [](const RgbImage& i, Wrap w) { return kawaseUp(i, 2 * i.width, 2 * i.height, 1.5, w); }},
        {"dualKawaseBlur", [](const RgbImage& i, Wrap w) { return dualKawaseBlur(i, 3, 2.0, w); }},
    };
}

const Wrap kWraps[] = {Wrap::Repeat, Wrap::ClampToEdge};

}  // namespace

TEST(BlurReference, EveryNormalisedBlurPreservesAConstant) {
    for (Wrap wrap : kWraps)
        for (const Method& m : normalisedMethods())
            for (auto [w, h] : {std::pair{13, 7}, std::pair{1, 1}, std::pair{1, 9}, std::pair{16, 16}}) {
                const RgbImage out = m.run(RgbImage(w, h, 0.37), wrap);
                EXPECT_LE(maxDeviation(out, 0.37), 1e-12) << m.name << " " << w << "x" << h;
            }
}

// The published LearnOpenGL weights sum to 0.9999994: each 1-D pass scales a
// constant by that, so N ping-pong pairs scale it by 0.9999994^(2N).
TEST(BlurReference, PublishedLearnOpenGLWeightsScaleAConstantByTheirSum) {
    EXPECT_NEAR(fullSum(learnOpenGLWeights()), 0.9999994, 1e-15);
    for (int passes : {1, 5}) {
        const RgbImage out = separableBlur(RgbImage(11, 6, 0.5), learnOpenGLWeights(), passes, Wrap::Repeat);
        EXPECT_LE(maxDeviation(out, 0.5 * std::pow(0.9999994, 2 * passes)), 1e-13) << passes;
        EXPECT_GT(maxDeviation(out, 0.5), 5e-7 * passes) << passes;
    }
}

// gaussblur.frag multiplies only the side taps by blurStrength: a constant c
// comes out as c (w0 + 2 s (w1 + w2 + w3 + w4))^2 after the two passes, not
// c * s, and (weights summing to 0.9999994) not exactly c even for s = 1.
TEST(BlurReference, WillemsScalesAConstantByItsExactFactor) {
    const double sides = 0.1945946 + 0.1216216 + 0.054054 + 0.016216;
    for (Wrap wrap : kWraps)
        for (double scale : {1.0, 1.7})
            for (double s : {0.5, 1.0, 1.5}) {
                const double factor = std::pow(0.227027 + 2 * s * sides, 2);
                const RgbImage out = willemsBlur(RgbImage(12, 9, 0.4), scale, s, wrap);
                EXPECT_LE(maxDeviation(out, 0.4 * factor), 1e-13) << "scale " << scale << " strength " << s;
            }
    // The seed's default blurStrength 1.5 brightens a constant by 1.92x.
    const RgbImage out = willemsBlur(RgbImage(12, 9, 0.4), 1.0, 1.5, Wrap::Repeat);
    EXPECT_NEAR(out.at(3, 3, 0) / 0.4, 1.9223423, 1e-6);
    EXPECT_GT(std::fabs(out.at(3, 3, 0) / 0.4 - 1.5), 0.4);  // and not the "times blurStrength" one might expect
}

// With blurScale 1 Willems' blur is the LearnOpenGL kernel applied once.
TEST(BlurReference, WillemsAtScaleOneIsOneLearnOpenGLPass) {
    const RgbImage img = noise(15, 10, 7);
    EXPECT_LE(maxAbsDiff(willemsBlur(img, 1.0, 1.0, Wrap::Repeat), separableBlur(img, learnOpenGLWeights(), 1, Wrap::Repeat)),
              1e-14);
}

TEST(BlurReference, SigmaOrRadiusZeroIsTheIdentity) {
    for (auto [sigma, radius] : {std::pair{0.0, 5}, std::pair{2.0, 0}, std::pair{-1.0, 3}, std::pair{double(NAN), 4}}) {
        const std::vector<double> w = gaussianWeights(sigma, radius);
        ASSERT_EQ(w.size(), 1u) << sigma << " " << radius;
        EXPECT_EQ(w[0], 1.0);
        const RgbImage img = noise(9, 5, 3);
        for (Wrap wrap : kWraps) EXPECT_EQ(gaussianBlur(img, sigma, radius, wrap).rgb, img.rgb);
    }
    // A tiny sigma underflows the side taps to 0, not to NaN.
    const std::vector<double> tiny = gaussianWeights(1e-3, 10);
    EXPECT_EQ(tiny[0], 1.0);
    for (double v : tiny) EXPECT_TRUE(std::isfinite(v));
}

TEST(BlurReference, RadiusWiderThanTheImageStaysFiniteAndNormalised) {
    for (auto [sigma, radius] : {std::pair{3.0, 50}, std::pair{1e6, 200}, std::pair{40.0, 1000}}) {
        const std::vector<double> w = gaussianWeights(sigma, radius);
        ASSERT_EQ(w.size(), size_t(radius) + 1);
        for (double v : w) ASSERT_TRUE(std::isfinite(v) && v >= 0);
        EXPECT_NEAR(fullSum(w), 1.0, 1e-12) << sigma << " " << radius;
        const RgbImage img = noise(5, 4, 11);
        for (Wrap wrap : kWraps) {
            const RgbImage out = gaussianBlur(img, sigma, radius, wrap);
            EXPECT_TRUE(allFinite(out));
            EXPECT_LE(maxDeviation(gaussianBlur(RgbImage(5, 4, 0.8), sigma, radius, wrap), 0.8), 1e-12);
            if (wrap == Wrap::Repeat) {  // a circular convolution keeps the mean
                double a = 0, b = 0;
                for (size_t i = 0; i < img.rgb.size(); ++i) a += img.rgb[i], b += out.rgb[i];
                EXPECT_NEAR(a, b, 1e-10);
            }
        }
    }
}

TEST(BlurReference, BilinearSampleFollowsGlLinear) {
    RgbImage img(4, 1);
    for (int x = 0; x < 4; ++x) img.set(x, 0, x + 1.0);  // 1 2 3 4
    EXPECT_EQ(bilinearSample(img, 2.5, 0.5, Wrap::Repeat)[0], 3.0);   // a texel centre
    EXPECT_EQ(bilinearSample(img, 2.0, 0.5, Wrap::Repeat)[0], 2.5);   // between texels 1 and 2
    EXPECT_EQ(bilinearSample(img, 1.75, 0.5, Wrap::Repeat)[0], 2.25);
    EXPECT_EQ(bilinearSample(img, 0.0, 0.5, Wrap::Repeat)[0], 2.5);   // texels 3 and 0, wrapped
    EXPECT_EQ(bilinearSample(img, 0.0, 0.5, Wrap::ClampToEdge)[0], 1.0);
    EXPECT_EQ(bilinearSample(img, 4.0, 0.5, Wrap::ClampToEdge)[0], 4.0);
    EXPECT_EQ(bilinearSample(img, 2.5, -3.7, Wrap::ClampToEdge)[0], 3.0);  // one row: y is moot
}

// Rakos' offsets for the 9-tap binomial kernel are 1.3846153846 and
// 3.2307692308; LearnOpenGL's rounded weights move the second by 2e-6.
TEST(BlurReference, LinearSampledWeightsMergePairs) {
    const LinearTaps t = linearSampledWeights(learnOpenGLWeights());
    ASSERT_EQ(t.offsets.size(), 3u);
    EXPECT_EQ(t.offsets[0], 0.0);
    EXPECT_NEAR(t.offsets[1], 1.3846153846, 1e-6);
    EXPECT_NEAR(t.offsets[2], 3.2307692308, 1e-5);
    EXPECT_NEAR(t.weights[1], 0.3162162, 1e-12);
    EXPECT_NEAR(t.weights[2], 0.07027, 1e-12);
    // An odd count of side taps leaves the last one alone.
    const LinearTaps odd = linearSampledWeights({0.4, 0.2, 0.1, 0.0});
    ASSERT_EQ(odd.offsets.size(), 3u);
    EXPECT_EQ(odd.offsets[2], 3.0);
    EXPECT_EQ(odd.weights[2], 0.0);
    EXPECT_NEAR(odd.offsets[1], 4.0 / 3.0, 1e-15);
}

TEST(BlurReference, LinearSampledBlurEqualsTheDiscreteOne) {
    const RgbImage img = noise(17, 11, 5);
    const std::vector<std::vector<double>> kernels = {learnOpenGLWeights(), gaussianWeights(2.5, 8),
                                                      gaussianWeights(2.5, 7), gaussianWeights(6, 25)};
    for (Wrap wrap : kWraps)
        for (const auto& w : kernels) {
            const double d = maxAbsDiff(linearSampledBlur(img, linearSampledWeights(w), 2, wrap), separableBlur(img, w, 2, wrap));
            EXPECT_LE(d, 1e-12) << "taps " << w.size();
        }
}

// Sol Trader's 5/6/5 at 1.2 texels is the discrete kernel 6/16 at 0 and
// 5/16 split 0.8 : 0.2 between 1 and 2 texels out.
TEST(BlurReference, SolTraderIsAFiveTapKernel) {
    const RgbImage img = noise(14, 9, 21);
    const std::vector<double> w = {6.0 / 16, 5.0 / 16 * 0.8, 5.0 / 16 * 0.2};
    for (Wrap wrap : kWraps)
        EXPECT_LE(maxAbsDiff(linearSampledBlur(img, solTraderTaps(1.2), 1, wrap), separableBlur(img, w, 1, wrap)), 1e-12);
}

// Convolution adds variances: N passes of the 9-tap kernel (sigma_1^2 =
// sum i^2 w_i / sum w_i = 2.8540469) have variance N sigma_1^2 exactly, and
// by the central limit theorem their shape tends to a Gaussian: the best
// fitting Gaussian's sigma / (sqrt(N) sigma_1) tends to 1 (measured: 1.038 at
// N = 1, 1.0025 at N = 16) and the fit's relative L2 residual halves each
// time N doubles (1.9e-2 at N = 1, 1.35e-3 at N = 16).
TEST(BlurReference, RepeatedLearnOpenGLKernelApproachesAGaussianOfSigmaSqrtN) {
    const std::vector<double> w = learnOpenGLWeights();
    double var1 = 0;
    for (size_t i = 1; i < w.size(); ++i) var1 += 2 * double(i * i) * w[i];
    var1 /= fullSum(w);
    EXPECT_NEAR(var1, 2.8540469, 1e-6);
    const int W = 241, centre = 120;
    double lastResidual = 1e9, lastRatioError = 1e9;
    for (int n : {1, 2, 4, 8, 16}) {
        RgbImage dot(W, 1);
        dot.set(centre, 0, 1.0);
        const RgbImage out = separableBlur(dot, w, n, Wrap::ClampToEdge);
        std::vector<double> r(W);
        double sum = 0, mean = 0, var = 0;
        for (int x = 0; x < W; ++x) sum += (r[size_t(x)] = out.at(x, 0, 0));
        for (int x = 0; x < W; ++x) r[size_t(x)] /= sum, mean += r[size_t(x)] * x;
        for (int x = 0; x < W; ++x) var += r[size_t(x)] * (x - mean) * (x - mean);
        EXPECT_NEAR(mean, centre, 1e-9);
        EXPECT_NEAR(var / (n * var1), 1.0, 1e-9) << n;
        // Least-squares fit of a sampled, normalised Gaussian (golden section).
        auto residual = [&](double sigma) {
            const std::vector<double> g = gaussianWeights(sigma, centre);
            double e = 0;
            for (int x = 0; x < W; ++x) {
                const double d = r[size_t(x)] - g[size_t(std::abs(x - centre))];
                e += d * d;
            }
            return e;
        };
        double lo = 0.3, hi = 30;
        const double phi = (std::sqrt(5.0) - 1) / 2;
        for (int it = 0; it < 200; ++it) {
            const double a = hi - phi * (hi - lo), b = lo + phi * (hi - lo);
            (residual(a) < residual(b) ? hi : lo) = (residual(a) < residual(b) ? b : a);
        }
        const double sigma = (lo + hi) / 2;
        double norm = 0;
        for (double v : r) norm += v * v;
        const double rel = std::sqrt(residual(sigma) / norm);
        const double ratioError = std::fabs(sigma / std::sqrt(n * var1) - 1.0);
        EXPECT_LT(ratioError, 0.05) << "N=" << n << " fitted sigma " << sigma;
        EXPECT_LT(ratioError, 0.75 * lastRatioError) << "N=" << n;
        EXPECT_LT(rel, 0.6 * lastResidual) << "N=" << n;
        lastResidual = rel, lastRatioError = ratioError;
    }
    EXPECT_LT(lastRatioError, 0.005);
    EXPECT_LT(lastResidual, 2e-3);
}

// Karis: a firefly (1000 in one texel, grey 0.1 elsewhere) reaches at most one
// tap of each box, so each box, and the output, stays below (1 + b) / 3 + b
// whatever its brightness; a plain average passes M / 16 of it.
TEST(BlurReference, KarisAverageKeepsAFireflyFromDominating) {
    const double b = 0.1, bound = (1 + b) / 3 + b;
    double karisAt1000 = 0;
    for (double m : {1000.0, 1e6}) {
        for (auto [fx, fy] : {std::pair{8, 8}, std::pair{7, 7}, std::pair{5, 9}}) {
            RgbImage img(16, 16, b);
            img.set(fx, fy, m);
            double karisMax = 0, plainMax = 0;
            const RgbImage k = codDownsample13(img, true, Wrap::Repeat), p = codDownsample13(img, false, Wrap::Repeat);
            for (double v : k.rgb) karisMax = std::max(karisMax, v);
            for (double v : p.rgb) plainMax = std::max(plainMax, v);
            EXPECT_LT(karisMax, bound) << m << " at " << fx << "," << fy;
            EXPECT_GT(plainMax, m / 16) << m << " at " << fx << "," << fy;
            if (m == 1000.0 && fx == 8) karisAt1000 = karisMax;
            if (m == 1e6 && fx == 8) {
                EXPECT_NEAR(karisMax, karisAt1000, 0.01);  // bounded, not proportional
            }
        }
    }
}

// Odd sizes and a dot on the centre texel: every operation is mirror
// symmetric, so the centroid must stay exactly on the centre (1e-9).
TEST(BlurReference, MipChainsKeepACentredDotCentred) {
    for (auto [w, h] : {std::pair{1, 1}, std::pair{1, 9}, std::pair{9, 1}, std::pair{37, 23}, std::pair{45, 45},
                        std::pair{17, 3}, std::pair{3, 17}, std::pair{5, 1}})
        for (Wrap wrap : kWraps) {
            RgbImage dot(w, h);
            dot.set(w / 2, h / 2, 1.0);
            RgbImage boxChain = dot;
            for (int k = 0; k < 4; ++k) boxChain = downsample2x(boxChain);
            std::vector<std::pair<std::string, RgbImage>> outs = {
                {"box chain", upsampleBilinear(boxChain, w, h, wrap)},
                {"CoD", codBloomChain(dot, 4, 1.0, wrap)},
                {"dual Kawase offset 1", dualKawaseBlur(dot, 4, 1.0, wrap)},
            };
            // Offset 2 misses texels on some odd sizes (see below).
            if (w != 37 && w != 17 && w != 3) outs.push_back({"dual Kawase offset 2", dualKawaseBlur(dot, 4, 2.0, wrap)});
            for (const auto& [name, out] : outs) {
                ASSERT_TRUE(allFinite(out)) << name << " " << w << "x" << h;
                double cx = 0, cy = 0;
                centroid(out, cx, cy);
                EXPECT_NEAR(cx, w / 2.0, 1e-9) << name << " " << w << "x" << h;
                EXPECT_NEAR(cy, h / 2.0, 1e-9) << name << " " << w << "x" << h;
            }
        }
}

// On odd sizes the output centres no longer sit on source texel corners,
// and the fixed-offset downsamples leave holes. A single bright texel at
// (18, 11) of 37x23 (output centre row 5 lands exactly on texel row 11, so
// only the dy = 0 taps see it): dual Kawase (offset 2: centre and diagonals 1
// texel out) misses it completely; CoD's 13 taps keep 2.85 % of the share a
// mass-preserving filter would (0.0066 of 0.2327), since its dy = 0 taps are
// 2 texels apart. The area box downsample2x keeps exactly that share. On even
// sizes dual Kawase reaches every texel.
TEST(BlurReference, OddSizesLeaveHolesInFixedOffsetDownsamples) {
    auto total = [](const RgbImage& img) {
        double s = 0;  // channel 0
        for (size_t i = 0; i < img.rgb.size(); i += 3) s += img.rgb[i];
        return s;
    };
    RgbImage odd(37, 23);
    odd.set(18, 11, 1.0);
    const double share = (18.0 * 11.0) / (37.0 * 23.0);
    EXPECT_EQ(total(kawaseDown(odd, 2.0, Wrap::Repeat)), 0.0);
    EXPECT_GT(total(kawaseDown(odd, 1.0, Wrap::Repeat)), 0.5 * share);
    EXPECT_NEAR(total(codDownsample13(odd, false, Wrap::Repeat)) / share, 0.0285, 0.001);
    EXPECT_NEAR(total(downsample2x(odd)), share, 1e-15);
    for (int y = 0; y < 22; ++y)
        for (int x = 0; x < 36; ++x) {
            RgbImage even(36, 22);
            even.set(x, y, 1.0);
            ASSERT_GT(total(kawaseDown(even, 2.0, Wrap::Repeat)), 0.5 * 0.25) << x << "," << y;
        }
}

// downsample2x on an odd size: 5 texels -> 2, footprints [0, 2.5) and
// [2.5, 5), the middle texel split half and half.
TEST(BlurReference, DownsampleOddSizeAveragesFootprints) {
    RgbImage row(5, 1);
    for (int x = 0; x < 5; ++x) row.set(x, 0, x + 1.0);
    const RgbImage out = downsample2x(row);
    ASSERT_EQ(out.width, 2);
    ASSERT_EQ(out.height, 1);
    EXPECT_NEAR(out.at(0, 0, 0), (1 + 2 + 0.5 * 3) / 2.5, 1e-15);
    EXPECT_NEAR(out.at(1, 0, 1), (0.5 * 3 + 4 + 5) / 2.5, 1e-15);
    RgbImage even(4, 2, 0.0);
    even.set(0, 0, 1.0), even.set(1, 1, 3.0);
    EXPECT_EQ(downsample2x(even).at(0, 0, 2), 1.0);  // (1 + 0 + 0 + 3) / 4
}

// A dot anywhere at least 12 texels from the edges, on even, odd and
// non-power-of-two sizes, three levels down (a coarsest texel is 8 input
// texels) and back up. Downsampling decides which coarse texels get the
// energy, so the centroid may move; the bounds, in coarsest texels, with what
// an exhaustive scan of dot positions measured:
//  - box chain: < 0.5, the box's quantisation bound (measured 0.44)
//  - CoD 13-tap + tent: < 0.06 where every level is even (measured 0.043),
//    < 0.15 where a level is odd (measured 0.111)
//  - dual Kawase, offset 2: < 0.55 (its non-separable 5-tap filter mixes the
//    x and y phases, and leaves holes on odd levels; measured 0.49)
// A size or half-texel mapping error shifts by whole texels and fails these.
TEST(BlurReference, MipChainsDoNotShiftAnOffCentreDot) {
    const int levels = 3;
    const double coarse = 8.0;
    struct Size {
        int w, h;
        bool evenChain;
    };
    for (Size sz : {Size{48, 48, true}, Size{56, 40, true}, Size{61, 37, false}, Size{50, 30, false}, Size{33, 65, false}}) {
        double worst[3] = {0, 0, 0};
        for (int dy = 12; dy < sz.h - 12; dy += 3)
            for (int dx = 12; dx < sz.w - 12; dx += 3) {
                RgbImage dot(sz.w, sz.h);
                dot.set(dx, dy, 1.0);
                RgbImage boxChain = dot;
                for (int k = 0; k < levels; ++k) boxChain = downsample2x(boxChain);
                const RgbImage outs[3] = {upsampleBilinear(boxChain, sz.w, sz.h, Wrap::ClampToEdge),
                                          codBloomChain(dot, levels, 1.0, Wrap::ClampToEdge),
                                          dualKawaseBlur(dot, levels, 2.0, Wrap::ClampToEdge)};
                for (int m = 0; m < 3; ++m) {
                    double cx = 0, cy = 0;
                    centroid(outs[m], cx, cy);
                    ASSERT_TRUE(std::isfinite(cx) && std::isfinite(cy)) << m << " " << sz.w << "x" << sz.h;
                    worst[m] = std::max({worst[m], std::fabs(cx - (dx + 0.5)) / coarse, std::fabs(cy - (dy + 0.5)) / coarse});
                }
            }
        EXPECT_LT(worst[0], 0.5) << "box chain " << sz.w << "x" << sz.h;
        EXPECT_LT(worst[1], sz.evenChain ? 0.06 : 0.15) << "CoD " << sz.w << "x" << sz.h;
        EXPECT_LT(worst[2], 0.55) << "dual Kawase " << sz.w << "x" << sz.h;
        EXPECT_GT(worst[0], 0.1) << "the box chain does quantise";  // the measurement sees shifts at all
    }
}
