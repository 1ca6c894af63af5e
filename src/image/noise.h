// glman's built-in noise textures (Noise2, unit 2; Noise3, unit 3), made on
// the CPU. No OpenGL here.
//
// Construction, for every channel k = 0..3 (r, g, b, a):
//   * periodic gradient (Perlin) noise: a lattice of cells[k] x cells[k]
//     (x cells[k]) cells across the whole texture, one pseudo-random unit
//     gradient at each lattice point (hashed from seed, k and the point, PCG
//     style), quintic fade 6t^5 - 15t^4 + 10t^3. The lattice wraps at
//     cells[k], so the texture tiles seamlessly (texel res-1 continues into
//     texel 0 exactly as any texel continues into its neighbour).
//   * cells[k] = 4 << k (4, 8, 16, 32: r lowest, each next channel twice the
//     frequency), capped at max(1, res / 2) so every cell spans at least two
//     texels; below res 64 the top octaves therefore stop doubling.
//   * sampled at texel centres: texel (i, j[, l]) is the noise at
//     s = (i + 0.5) / res, t = (j + 0.5) / res[, r = (l + 0.5) / res], in
//     texture coordinates (t = 0 at the bottom; see below for storage order).
//   * amplitude: each channel is standardised over the whole texture, then
//       value = 0.5 + kNoiseSigma0 / 2^k * (n - mean(n)) / std(n)
//     so channel k has mean 0.5 and standard deviation exactly
//     0.125 / 2^k (0.125, 0.0625, 0.03125, 0.015625) before rounding: the
//     standard deviation halves per octave by construction, at every
//     resolution and seed. (The mean of periodic gradient noise sampled at
//     texel centres is already 0 exactly, but its spread is not fixed: with a
//     fixed amplitude per octave, the measured 2-D g/r std ratio ranged over
//     0.43..0.67 across 40 seeds, since r has only 4x4 cells.) Measured over
//     200 2-D and 30 3-D seeds, no texel lay more than 3.6 standard
//     deviations from 0.5, so r stays within about [0.05, 0.95], g within
//     [0.27, 0.73], and no byte clips. r+g+b+a has mean 2 and std
//     0.125 * sqrt(1 + 1/4 + 1/16 + 1/64) = 0.144, so glman's (sum - 1) / 2
//     lies well inside 0..1. Constant noise (res 1) becomes 0.5.
//   * U8: round(clamp(value, 0, 1) * 255). F32: the value itself, unclamped.
//
// Deterministic: the same (res, seed, type) gives identical texels (integer
// hashing, gradients by rejection sampling with only sqrt, no sin/cos; float
// maths in a fixed order, so builds differ at most where a compiler contracts
// to FMA, which can move a byte by one).
//
// Speed (one core): 3-D res 64 takes 12 ms optimised (-O2), about 100 ms in a
// Debug build; res 128 175 ms optimised. 2-D res 256: 2 ms.
#pragma once
#include <cstdint>

#include "image/image.h"

namespace glimmer {

inline constexpr std::uint32_t kNoiseSeed = 0x9E3779B9u;  // the default seed
inline constexpr double kNoiseSigma0 = 0.125;              // std of channel r

// A res x res RGBA texture (U8 as glman made it, or F32). Rows in Image order
// (row 0 is the top, t = 1), like a loaded picture: the renderer's usual row
// flip applies. res < 1 gives an empty Image.
Image makeNoise2D(int res, std::uint32_t seed = kNoiseSeed, Image::Type type = Image::Type::U8);

// A res^3 RGBA volume in OpenGL order (x fastest, then y from the bottom,
// then z), ready for glTexImage3D like a loaded Volume. res < 1 gives an
// empty Volume.
Volume makeNoise3D(int res, std::uint32_t seed = kNoiseSeed, Image::Type type = Image::Type::U8);

// The lattice cells across the texture for channel `channel` (0..3) at `res`.
int noiseCells(int res, int channel);

}  // namespace glimmer
