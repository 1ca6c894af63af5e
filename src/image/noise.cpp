// glman's built-in noise textures: four octaves of periodic gradient noise,
// one a channel. See noise.h for the construction and the amplitude rule.
#include "image/noise.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace glimmer {
namespace {

// PCG-style integer hash (Jarzynski & Olano, "Hash Functions for GPU
// Rendering", 2020): one 32-bit LCG step and the RXS-M-XS output permutation.
std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [-1, 1) from the top 24 bits of a hash.
double signedUnit(std::uint32_t h) { return double(h >> 8) * (2.0 / 16777216.0) - 1.0; }

// One pseudo-random unit gradient of `dims` components for every lattice
// point of a cells^dims periodic lattice, x fastest. Uniform directions by
// rejection from the cube [-1,1)^dims (no libm transcendentals, so no
// platform-dependent sin/cos).
std::vector<float> makeGradients(int dims, int cells, std::uint32_t seed, int channel) {
    std::size_t points = 1;
    for (int d = 0; d < dims; ++d) points *= std::size_t(cells);
    std::vector<float> g(points * std::size_t(dims));
    const std::uint32_t base = pcgHash(seed ^ pcgHash(std::uint32_t(channel) + 0x632BE5ABu));
    for (std::size_t p = 0; p < points; ++p) {
        const std::uint32_t x = std::uint32_t(p % std::size_t(cells));
        const std::uint32_t y = std::uint32_t(p / std::size_t(cells) % std::size_t(cells));
        const std::uint32_t z = dims == 3 ? std::uint32_t(p / (std::size_t(cells) * std::size_t(cells))) : 0u;
        std::uint32_t h = pcgHash(base ^ pcgHash(x ^ pcgHash(y ^ pcgHash(z))));
        double v[3] = {0, 0, 0};
        for (;;) {
            double len2 = 0;
            for (int d = 0; d < dims; ++d) {
                h = pcgHash(h);
                v[d] = signedUnit(h);
                len2 += v[d] * v[d];
            }
            if (len2 > 1e-4 && len2 <= 1.0) {
                const double inv = 1.0 / std::sqrt(len2);
                for (int d = 0; d < dims; ++d) g[p * std::size_t(dims) + std::size_t(d)] = float(v[d] * inv);
                break;
            }
        }
    }
    return g;
}

// Where texel centre i falls on a periodic lattice of `cells` cells across
// `res` texels: the cell's two lattice indices (wrapped), the offset inside
// the cell and its fade weight.
struct AxisSample {
    int c0, c1;
    float f, u;
};

std::vector<AxisSample> axisSamples(int res, int cells) {
    std::vector<AxisSample> s(static_cast<std::size_t>(res));
    for (int i = 0; i < res; ++i) {
        const double x = (i + 0.5) * double(cells) / double(res);
        const int c = int(std::floor(x));
        const double f = x - c;
        const double u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);  // 6t^5 - 15t^4 + 10t^3
        s[std::size_t(i)] = {c % cells, (c + 1) % cells, float(f), float(u)};
    }
    return s;
}

float lerp(float a, float b, float t) { return a + t * (b - a); }

// Raw periodic gradient noise for one channel, dims = 2 or 3, texels in
// texture-coordinate order (x fastest, then y from the bottom, then z).
std::vector<float> rawNoise(int dims, int res, std::uint32_t seed, int channel) {
    const int cells = noiseCells(res, channel);
    const std::vector<float> g = makeGradients(dims, cells, seed, channel);
    const std::vector<AxisSample> ax = axisSamples(res, cells);
    const std::size_t n = std::size_t(res);
    const std::size_t cs = std::size_t(cells);
    std::vector<float> out(dims == 3 ? n * n * n : n * n);
    std::size_t at = 0;
    if (dims == 2) {
        auto dot2 = [&](int cx, int cy, float fx, float fy) {
            const float* gp = &g[(std::size_t(cy) * cs + std::size_t(cx)) * 2];
            return gp[0] * fx + gp[1] * fy;
        };
        for (const AxisSample& sy : ax)
            for (const AxisSample& sx : ax) {
                const float n00 = dot2(sx.c0, sy.c0, sx.f, sy.f);
                const float n10 = dot2(sx.c1, sy.c0, sx.f - 1, sy.f);
                const float n01 = dot2(sx.c0, sy.c1, sx.f, sy.f - 1);
                const float n11 = dot2(sx.c1, sy.c1, sx.f - 1, sy.f - 1);
                out[at++] = lerp(lerp(n00, n10, sx.u), lerp(n01, n11, sx.u), sy.u);
            }
        return out;
    }
    auto dot3 = [&](int cx, int cy, int cz, float fx, float fy, float fz) {
        const float* gp = &g[((std::size_t(cz) * cs + std::size_t(cy)) * cs + std::size_t(cx)) * 3];
        return gp[0] * fx + gp[1] * fy + gp[2] * fz;
    };
    for (const AxisSample& sz : ax)
        for (const AxisSample& sy : ax)
            for (const AxisSample& sx : ax) {
                const float n000 = dot3(sx.c0, sy.c0, sz.c0, sx.f, sy.f, sz.f);
                const float n100 = dot3(sx.c1, sy.c0, sz.c0, sx.f - 1, sy.f, sz.f);
                const float n010 = dot3(sx.c0, sy.c1, sz.c0, sx.f, sy.f - 1, sz.f);
                const float n110 = dot3(sx.c1, sy.c1, sz.c0, sx.f - 1, sy.f - 1, sz.f);
                const float n001 = dot3(sx.c0, sy.c0, sz.c1, sx.f, sy.f, sz.f - 1);
                const float n101 = dot3(sx.c1, sy.c0, sz.c1, sx.f - 1, sy.f, sz.f - 1);
                const float n011 = dot3(sx.c0, sy.c1, sz.c1, sx.f, sy.f - 1, sz.f - 1);
                const float n111 = dot3(sx.c1, sy.c1, sz.c1, sx.f - 1, sy.f - 1, sz.f - 1);
                const float lo = lerp(lerp(n000, n100, sx.u), lerp(n010, n110, sx.u), sy.u);
                const float hi = lerp(lerp(n001, n101, sx.u), lerp(n011, n111, sx.u), sy.u);
                out[at++] = lerp(lo, hi, sz.u);
            }
    return out;
}

// Shifts and scales `v` in place to mean 0.5 and standard deviation `sigma`
// (constant input becomes 0.5).
void standardise(std::vector<float>& v, double sigma) {
    if (v.empty()) return;
    double sum = 0;
    for (float x : v) sum += x;
    const double mean = sum / double(v.size());
    double sq = 0;
    for (float x : v) sq += (x - mean) * (x - mean);
    const double sd = std::sqrt(sq / double(v.size()));
    const double scale = sd > 1e-12 ? sigma / sd : 0.0;
    for (float& x : v) x = float(0.5 + (x - mean) * scale);
}

// All four channels, standardised, in texture-coordinate order.
void channels(int dims, int res, std::uint32_t seed, std::vector<float> (&ch)[4]) {
    for (int k = 0; k < 4; ++k) {
        ch[k] = rawNoise(dims, res, seed, k);
        standardise(ch[k], kNoiseSigma0 / double(1 << k));
    }
}

std::uint8_t toByte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

int noiseCells(int res, int channel) { return std::max(1, std::min(4 << channel, res / 2)); }

Image makeNoise2D(int res, std::uint32_t seed, Image::Type type) {
    if (res < 1) return {};
    std::vector<float> ch[4];
    channels(2, res, seed, ch);
    Image img = type == Image::Type::U8 ? Image::rgba8(res, res) : Image::rgbaF32(res, res);
    const std::size_t n = std::size_t(res);
    for (std::size_t row = 0; row < n; ++row) {
        const std::size_t t = n - 1 - row;  // Image row 0 is the top (t = 1)
        for (std::size_t x = 0; x < n; ++x)
            for (int k = 0; k < 4; ++k) {
                const float v = ch[k][t * n + x];
                const std::size_t at = (row * n + x) * 4 + std::size_t(k);
                if (type == Image::Type::U8)
                    img.u8[at] = toByte(v);
                else
                    img.f32[at] = v;
            }
    }
    return img;
}

Volume makeNoise3D(int res, std::uint32_t seed, Image::Type type) {
    if (res < 1) return {};
    std::vector<float> ch[4];
    channels(3, res, seed, ch);
    Volume v;
    v.width = v.height = v.depth = res;
    v.type = type;
    const std::size_t texels = ch[0].size();
    if (type == Image::Type::U8)
        v.u8.resize(texels * 4);
    else
        v.f32.resize(texels * 4);
    for (std::size_t i = 0; i < texels; ++i)
        for (int k = 0; k < 4; ++k) {
            if (type == Image::Type::U8)
                v.u8[i * 4 + std::size_t(k)] = toByte(ch[k][i]);
            else
                v.f32[i * 4 + std::size_t(k)] = ch[k][i];
        }
    return v;
}

}  // namespace glimmer
