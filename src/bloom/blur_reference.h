// Double-precision CPU references of the blur methods a bloom pass may use,
// for `glimmer tradeoff`: a GPU blur is compared with the reference of the
// SAME kernel (numerical error) and with gaussianBlur of matching sigma
// (model error). Never on the render path.
//
// Conventions, shared by every function here:
//  - Images are RgbImage (row 0 at the top, doubles, no clamping anywhere).
//  - A texel (i, j) has its centre at (i + 0.5, j + 0.5) in texel
//    coordinates, as OpenGL's texture coordinates times the texture size.
//  - A pass writing a w' x h' target from a w x h source maps output texel
//    (i, j) to source position ((i + 0.5) * w / w', (j + 0.5) * h / h'): a
//    full-screen quad over the target, sampling the source at the fragment's
//    uv. Tap offsets are in SOURCE texels.
//  - Lookups outside the image follow `Wrap`, like GL_REPEAT and
//    GL_CLAMP_TO_EDGE.
//  - A half-size target is max(1, w / 2) x max(1, h / 2) (integer division),
//    the size of OpenGL's next mip level.
//  - Symmetric 1-D kernels are given by their half: w[0] is the centre tap,
//    w[i] (i >= 1) the weight of both taps at +i and -i. They sum to 1 when
//    w[0] + 2 * (w[1] + ... + w[n]) == 1.
#pragma once
#include <array>
#include <vector>

#include "bloom/superblur_reference.h"

namespace glimmer {

enum class Wrap { Repeat, ClampToEdge };

// Index i of an axis of n texels, wrapped (Repeat) or clamped (ClampToEdge).
int wrapIndex(int i, int n, Wrap wrap);

// ---- Gaussian (the model-error reference) ---------------------------------

// Half of a sampled Gaussian exp(-i^2 / (2 sigma^2)), i = 0..radius, in
// double, normalised so the full kernel sums to 1. sigma <= 0 or radius <= 0
// gives the identity {1}. The weights do not depend on any image size: a
// radius wider than the image is still finite and normalised (the taps wrap
// or clamp at lookup).
std::vector<double> gaussianWeights(double sigma, int radius);

// Separable exact Gaussian: gaussianWeights(sigma, radius) horizontally,
// then vertically, once.
RgbImage gaussianBlur(const RgbImage& img, double sigma, int radius, Wrap wrap);

// ---- Discrete separable kernels ---------------------------------------------

// The 9-tap Gaussian of LearnOpenGL's "Bloom" chapter (and of Sascha Willems'
// Vulkan bloom): {0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216}, as
// published. They sum to 0.9999994, not 1.
std::vector<double> learnOpenGLWeights();

// LearnOpenGL "Bloom" ping-pong: the symmetric kernel `weights` (a half, see
// above) applied horizontally then vertically at whole-texel offsets, that
// pair repeated `passes` times (LearnOpenGL's amount = 2 * passes). The
// weights are used as given, not renormalised. passes <= 0 returns img.
RgbImage separableBlur(const RgbImage& img, const std::vector<double>& weights, int passes, Wrap wrap);

// ---- Linear sampling (bilinear tap merging) ---------------------------------

// Taps for the bilinear trick (Rideout, "Bloom"; Rakos, "Efficient Gaussian
// blur with linear sampling", 2010; Sol Trader's 5/6/5): offsets[0] == 0 is
// the centre with weights[0] == w[0]; then neighbouring discrete taps (1,2),
// (3,4), ... are merged into one tap at offset (o1 w1 + o2 w2) / (w1 + w2)
// with weight w1 + w2, applied at +offset and -offset. An odd last tap stays
// alone at its own offset. A pair whose weights sum to 0 keeps offset o1.
struct LinearTaps {
    std::vector<double> offsets;  // in texels, offsets[0] == 0
    std::vector<double> weights;  // per side for k >= 1, like the half kernel
};
LinearTaps linearSampledWeights(const std::vector<double>& weights);

// Sol Trader's bloom blur: 6/16 at the centre and 5/16 at +-offset texels
// (the seed uses 1.2 texels), sampled bilinearly.
LinearTaps solTraderTaps(double offsetTexels);

// What GL_LINEAR returns (without the GPU's 8-bit sub-texel weight
// quantisation) at texel coordinates (x, y): texel centres at i + 0.5, the
// four texels around (x - 0.5, y - 0.5) blended by their fractional parts.
std::array<double, 3> bilinearSample(const RgbImage& img, double x, double y, Wrap wrap);

// LinearTaps applied horizontally then vertically, `passes` times, each tap a
// bilinearSample at the output texel's centre +- offset along the pass axis.
// With taps from linearSampledWeights(w) it equals separableBlur(w) to
// rounding (1e-12).
RgbImage linearSampledBlur(const RgbImage& img, const LinearTaps& taps, int passes, Wrap wrap);

// Sascha Willems' Vulkan "bloom" example, gaussblur.frag: centre tap
// weight[0], then for i = 1..4 the taps at +-i * blurScale texels (bilinear
// where blurScale is fractional) times weight[i] * blurStrength. One
// horizontal and one vertical pass (the seed's two blurdirection pipelines;
// the order does not change the result). Note that the shader scales only the
// side taps: a constant c comes out as c * (w0 + 2 s (w1+w2+w3+w4))^2, not
// c * s, and not c even for s == 1 (the published weights sum to 0.9999994).
RgbImage willemsBlur(const RgbImage& img, double blurScale, double blurStrength, Wrap wrap);

// ---- Resampling -------------------------------------------------------------

// Half-size box filter: each output texel is the area-weighted mean of its
// footprint in the source. For even sizes that is exactly the 2x2 box
// average. For an odd size (w = 2k + 1 -> k texels) each footprint is
// w / k source texels wide and straddles a texel, which it takes
// fractionally: the image is not shifted, the mean is kept, and no texel
// outside the image is read (so no wrap mode). A size of 1 stays 1.
RgbImage downsample2x(const RgbImage& img);

// Bilinear resize to w x h (GL_LINEAR at each output texel's centre mapped
// into the source, see the conventions above).
RgbImage upsampleBilinear(const RgbImage& img, int w, int h, Wrap wrap);

// ---- "Next Generation Post Processing in Call of Duty: Advanced Warfare",
//      Jorge Jimenez, SIGGRAPH 2014 -----------------------------------------

// The 13-tap downsample to half size. Around the output centre p (in source
// texels), 13 bilinear taps: e at p; a b c / d f / g h i at offsets of
// (+-2 or 0, +-2 or 0); j k l m at (+-1, +-1). They form five 2x2 boxes, each
// averaged: the centre box (j k l m) weighs 0.5, the four overlapping corner
// boxes (a b d e), (b c e f), (d e g h), (e f h i) weigh 0.125 each. Per tap
// that is e 0.125, b d f h 0.0625, a c g i 0.03125, j k l m 0.125; sum 1.
//
// karis: the slides' "partial Karis average" against fireflies, for the
// first downsample: within each 2x2 box the 4 taps are averaged with weights
// 1 / (1 + luma(tap)) (Brian Karis, "Graphic Rants: Tone mapping", 2013),
// normalised by their sum, luma Rec. 709 (0.2126, 0.7152, 0.0722) clamped at
// 0; the boxes are then combined with the fixed 0.5 / 4 x 0.125. A constant
// is still preserved. A lone bright texel reaches at most one tap of each box
// (a box's taps are 2 texels apart), so on a grey background b each box,
// hence the output, stays below (1 + b) / 3 + b however bright it is.
//
// On odd sizes the output centres leave the source texel corners and the
// taps no longer cover every texel evenly: a texel on the row of a centre can
// keep under 3 % of its share (tests/reference measure it).
RgbImage codDownsample13(const RgbImage& img, bool karis, Wrap wrap);

// The 3x3 tent upsample to w x h: 9 bilinear taps of the (smaller) source at
// p + radius * (dx, dy), dx, dy in {-1, 0, 1}, weights (1 2 1) x (1 2 1) / 16.
// radius in source texels (the slides' filter radius; 1 by default).
RgbImage codUpsampleTent(const RgbImage& small, int w, int h, double radius, Wrap wrap);

// The whole chain, `levels` >= 1 halvings: mip1 = codDownsample13(img, Karis),
// mip k = codDownsample13(mip k-1, plain) for k = 2..levels; then from the
// smallest up, up_k = mip_k + tent(up_{k+1}) ("upsample and accumulate");
// finally tent(up_1) to the input's size, divided by `levels`. The chain adds
// the levels, as in the slides; the division makes the result a mean of them
// so a constant image is preserved (a GPU version that does not divide
// compares against levels * this). levels < 1 returns img.
RgbImage codBloomChain(const RgbImage& img, int levels, double upsampleRadius, Wrap wrap);

// ---- Dual Kawase: Marius Bjorge, "Bandwidth-Efficient Rendering",
//      SIGGRAPH 2015 ----------------------------------------------------------

// Downsample to half size: (4 * s(p) + s(p + (+-h, +-h)) for the 4
// diagonals) / 8, with h = 0.5 * offset SOURCE texels (the usual
// "halfpixel * offset", halfpixel = 0.5 / source size). offset 1 lands the
// diagonals on the 4 texel centres around p, i.e. a plain 2x2 box; larger
// offsets blur more (offset 2 puts them half a destination texel out, at the
// corners of the output texel's footprint). On odd sizes offset 2 can miss a
// texel entirely (tests/reference: (18, 11) of 37x23).
RgbImage kawaseDown(const RgbImage& img, double offset, Wrap wrap);

// Upsample to w x h: taps s(p + (+-2h, 0)), s(p + (0, +-2h)) weight 1 and
// s(p + (+-h, +-h)) weight 2, all / 12, h = 0.5 * offset SOURCE (smaller)
// texels.
RgbImage kawaseUp(const RgbImage& small, int w, int h, double offset, Wrap wrap);

// `iterations` kawaseDown, then kawaseUp back through the same sizes to the
// input's size. iterations < 1 returns img.
RgbImage dualKawaseBlur(const RgbImage& img, int iterations, double offset, Wrap wrap);

}  // namespace glimmer
