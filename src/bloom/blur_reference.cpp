#include "bloom/blur_reference.h"

#include <algorithm>
#include <cmath>

namespace glimmer {
namespace {

using Rgb = std::array<double, 3>;

int halfSize(int n) { return std::max(1, n / 2); }

// Source position (texel coordinates) of output texel i's centre, for an
// output of n texels over a source of srcN texels.
double sourcePos(int i, int n, int srcN) { return (i + 0.5) * double(srcN) / double(n); }

void addScaled(Rgb& acc, const Rgb& v, double w) {
    for (int c = 0; c < 3; ++c) acc[c] += w * v[c];
}

void store(RgbImage& img, int x, int y, const Rgb& v) {
    for (int c = 0; c < 3; ++c) img.at(x, y, c) = v[c];
}

// One pass of a symmetric whole-texel kernel along x (horizontal) or y.
RgbImage convolveAxis(const RgbImage& in, const std::vector<double>& w, bool horizontal, Wrap wrap) {
    RgbImage out(in.width, in.height);
    const int r = int(w.size()) - 1;
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int i = -r; i <= r; ++i) {
                    const double wi = w[size_t(std::abs(i))];
                    sum += horizontal ? wi * in.at(wrapIndex(x + i, in.width, wrap), y, c)
                                      : wi * in.at(x, wrapIndex(y + i, in.height, wrap), c);
                }
                out.at(x, y, c) = sum;
            }
        }
    }
    return out;
}

// One pass of linear-sampled taps along an axis.
RgbImage linearAxis(const RgbImage& in, const LinearTaps& taps, bool horizontal, Wrap wrap) {
    RgbImage out(in.width, in.height);
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            Rgb acc{0, 0, 0};
            for (size_t k = 0; k < taps.offsets.size(); ++k) {
                const double o = taps.offsets[k], w = taps.weights[k];
                if (k == 0 && o == 0.0) {
                    addScaled(acc, bilinearSample(in, px, py, wrap), w);
                    continue;
                }
                const double dx = horizontal ? o : 0.0, dy = horizontal ? 0.0 : o;
                addScaled(acc, bilinearSample(in, px + dx, py + dy, wrap), w);
                addScaled(acc, bilinearSample(in, px - dx, py - dy, wrap), w);
            }
            store(out, x, y, acc);
        }
    }
    return out;
}

double luma709(const Rgb& v) { return 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2]; }

// Area-weighted 1-D resampling matrix from n source texels to m, each output
// texel averaging its footprint [i n/m, (i+1) n/m).
std::vector<std::vector<std::pair<int, double>>> areaWeights(int n, int m) {
    std::vector<std::vector<std::pair<int, double>>> rows(static_cast<size_t>(m));
    const double scale = double(n) / double(m);
    for (int i = 0; i < m; ++i) {
        const double a = i * scale, b = (i + 1) * scale;
        for (int k = int(std::floor(a)); k < n && k < b; ++k) {
            const double overlap = std::min(b, k + 1.0) - std::max(a, double(k));
            if (overlap > 0) rows[size_t(i)].push_back({k, overlap / scale});
        }
    }
    return rows;
}

}  // namespace

int wrapIndex(int i, int n, Wrap wrap) {
    if (wrap == Wrap::Repeat) return ((i % n) + n) % n;
    return std::clamp(i, 0, n - 1);
}

// Sampled Gaussian, the continuous kernel exp(-x^2 / 2 sigma^2) at integer x,
// renormalised over the truncated support [-radius, radius].
std::vector<double> gaussianWeights(double sigma, int radius) {
    if (!(sigma > 0) || radius <= 0) return {1.0};
    std::vector<double> w(size_t(radius) + 1);
    double sum = 0;
    for (int i = 0; i <= radius; ++i) {
        w[size_t(i)] = std::exp(-double(i) * double(i) / (2.0 * sigma * sigma));
        sum += i == 0 ? w[0] : 2.0 * w[size_t(i)];
    }
    for (double& v : w) v /= sum;  // sum >= w[0] == 1, never 0
    return w;
}

RgbImage gaussianBlur(const RgbImage& img, double sigma, int radius, Wrap wrap) {
    return separableBlur(img, gaussianWeights(sigma, radius), 1, wrap);
}

// LearnOpenGL, "Bloom" (Joey de Vries): uniform float weight[5].
std::vector<double> learnOpenGLWeights() { return {0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216}; }

// LearnOpenGL "Bloom": horizontal then vertical, ping-ponged `passes` times.
RgbImage separableBlur(const RgbImage& img, const std::vector<double>& weights, int passes, Wrap wrap) {
    RgbImage cur = img;
    if (weights.empty()) return cur;
    for (int p = 0; p < passes; ++p) {
        cur = convolveAxis(cur, weights, true, wrap);
        cur = convolveAxis(cur, weights, false, wrap);
    }
    return cur;
}

// Rakos 2010 / Rideout: two discrete taps o1, o2 read by one bilinear fetch
// at (o1 w1 + o2 w2) / (w1 + w2) with weight w1 + w2.
LinearTaps linearSampledWeights(const std::vector<double>& weights) {
    LinearTaps t;
    if (weights.empty()) return t;
    t.offsets.push_back(0.0);
    t.weights.push_back(weights[0]);
    for (size_t i = 1; i < weights.size(); i += 2) {
        const double o1 = double(i), w1 = weights[i];
        if (i + 1 >= weights.size()) {
            t.offsets.push_back(o1);
            t.weights.push_back(w1);
            break;
        }
        const double o2 = double(i + 1), w2 = weights[i + 1];
        const double sum = w1 + w2;
        t.offsets.push_back(sum != 0.0 ? (o1 * w1 + o2 * w2) / sum : o1);
        t.weights.push_back(sum);
    }
    return t;
}

// Sol Trader, "Bloom, part 2": c = (5 s(uv - off) + 6 s(uv) + 5 s(uv + off)) / 16.
LinearTaps solTraderTaps(double offsetTexels) { return {{0.0, offsetTexels}, {6.0 / 16.0, 5.0 / 16.0}}; }

// GL_LINEAR (OpenGL 4.6 core, 8.14.2): i0 = floor(u - 0.5), alpha = frac(u - 0.5).
std::array<double, 3> bilinearSample(const RgbImage& img, double x, double y, Wrap wrap) {
    const double fx = x - 0.5, fy = y - 0.5;
    const double x0f = std::floor(fx), y0f = std::floor(fy);
    const double ax = fx - x0f, ay = fy - y0f;
    const int x0 = int(x0f), y0 = int(y0f);
    const int xa = wrapIndex(x0, img.width, wrap), xb = wrapIndex(x0 + 1, img.width, wrap);
    const int ya = wrapIndex(y0, img.height, wrap), yb = wrapIndex(y0 + 1, img.height, wrap);
    Rgb out{};
    for (int c = 0; c < 3; ++c) {
        // Zero weights skip their texels, so an exact hit reads one texel only
        // (and an Inf next door does not turn it into NaN).
        double top = img.at(xa, ya, c) * (1 - ax);
        if (ax != 0) top += img.at(xb, ya, c) * ax;
        double v = top * (1 - ay);
        if (ay != 0) {
            double bottom = img.at(xa, yb, c) * (1 - ax);
            if (ax != 0) bottom += img.at(xb, yb, c) * ax;
            v += bottom * ay;
        }
        out[size_t(c)] = v;
    }
    return out;
}

RgbImage linearSampledBlur(const RgbImage& img, const LinearTaps& taps, int passes, Wrap wrap) {
    RgbImage cur = img;
    if (taps.offsets.empty()) return cur;
    for (int p = 0; p < passes; ++p) {
        cur = linearAxis(cur, taps, true, wrap);
        cur = linearAxis(cur, taps, false, wrap);
    }
    return cur;
}

// Sascha Willems, Vulkan examples, "bloom", shaders/glsl/bloom/gaussblur.frag.
RgbImage willemsBlur(const RgbImage& img, double blurScale, double blurStrength, Wrap wrap) {
    const std::vector<double> weight = learnOpenGLWeights();
    LinearTaps taps;
    taps.offsets.push_back(0.0);
    taps.weights.push_back(weight[0]);
    for (int i = 1; i < 5; ++i) {
        taps.offsets.push_back(i * blurScale);
        taps.weights.push_back(weight[size_t(i)] * blurStrength);
    }
    RgbImage h = linearAxis(img, taps, true, wrap);
    return linearAxis(h, taps, false, wrap);
}

// Box (area) filter to the next mip size.
RgbImage downsample2x(const RgbImage& img) {
    const int w = halfSize(img.width), h = halfSize(img.height);
    const auto wx = areaWeights(img.width, w), wy = areaWeights(img.height, h);
    RgbImage out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (auto [sy, ky] : wy[size_t(y)])
                    for (auto [sx, kx] : wx[size_t(x)]) sum += ky * kx * img.at(sx, sy, c);
                out.at(x, y, c) = sum;
            }
    return out;
}

RgbImage upsampleBilinear(const RgbImage& img, int w, int h, Wrap wrap) {
    RgbImage out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            store(out, x, y,
                  bilinearSample(img, sourcePos(x, w, img.width), sourcePos(y, h, img.height), wrap));
    return out;
}

// Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced
// Warfare", slides 'Downsampling' (13 taps, 5 boxes) and 'Karis average'.
RgbImage codDownsample13(const RgbImage& img, bool karis, Wrap wrap) {
    const int w = halfSize(img.width), h = halfSize(img.height);
    RgbImage out(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double px = sourcePos(x, w, img.width), py = sourcePos(y, h, img.height);
            auto s = [&](double dx, double dy) { return bilinearSample(img, px + dx, py + dy, wrap); };
            const Rgb a = s(-2, -2), b = s(0, -2), c = s(2, -2);
            const Rgb d = s(-2, 0), e = s(0, 0), f = s(2, 0);
            const Rgb g = s(-2, 2), hh = s(0, 2), i = s(2, 2);
            const Rgb j = s(-1, -1), k = s(1, -1), l = s(-1, 1), m = s(1, 1);
            const Rgb* boxes[5][4] = {{&j, &k, &l, &m}, {&a, &b, &d, &e}, {&b, &c, &e, &f},
                                      {&d, &e, &g, &hh}, {&e, &f, &hh, &i}};
            const double boxWeight[5] = {0.5, 0.125, 0.125, 0.125, 0.125};
            Rgb acc{0, 0, 0};
            for (int bx = 0; bx < 5; ++bx) {
                // A box's value: the plain mean of its 4 taps, or their Karis
                // average, sum k_t s_t / sum k_t with k_t = 1 / (1 + luma(s_t)).
                Rgb mean{0, 0, 0};
                double total = 0;
                for (const Rgb* t : boxes[bx]) {
                    const double k = karis ? 1.0 / (1.0 + std::max(0.0, luma709(*t))) : 1.0;
                    addScaled(mean, *t, k);
                    total += k;
                }
                addScaled(acc, mean, boxWeight[bx] / total);
            }
            store(out, x, y, acc);
        }
    }
    return out;
}

// Jimenez 2014, 'Upsampling': 3x3 tent, summed into the next level up.
RgbImage codUpsampleTent(const RgbImage& small, int w, int h, double radius, Wrap wrap) {
    RgbImage out(w, h);
    const double k[3] = {1, 2, 1};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double px = sourcePos(x, w, small.width), py = sourcePos(y, h, small.height);
            Rgb acc{0, 0, 0};
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    addScaled(acc, bilinearSample(small, px + dx * radius, py + dy * radius, wrap),
                              k[dx + 1] * k[dy + 1] / 16.0);
            store(out, x, y, acc);
        }
    }
    return out;
}

RgbImage codBloomChain(const RgbImage& img, int levels, double upsampleRadius, Wrap wrap) {
    if (levels < 1) return img;
    std::vector<RgbImage> mips;
    mips.push_back(codDownsample13(img, true, wrap));
    for (int k = 2; k <= levels; ++k) mips.push_back(codDownsample13(mips.back(), false, wrap));
    RgbImage up = mips.back();
    for (int k = levels - 2; k >= 0; --k) {
        RgbImage t = codUpsampleTent(up, mips[size_t(k)].width, mips[size_t(k)].height, upsampleRadius, wrap);
        for (size_t n = 0; n < t.rgb.size(); ++n) t.rgb[n] += mips[size_t(k)].rgb[n];
        up = std::move(t);
    }
    RgbImage out = codUpsampleTent(up, img.width, img.height, upsampleRadius, wrap);
    for (double& v : out.rgb) v /= levels;
    return out;
}

// Bjorge 2015, "Bandwidth-Efficient Rendering", dual filter downsample.
RgbImage kawaseDown(const RgbImage& img, double offset, Wrap wrap) {
    const int w = halfSize(img.width), h = halfSize(img.height);
    const double hp = 0.5 * offset;
    RgbImage out(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double px = sourcePos(x, w, img.width), py = sourcePos(y, h, img.height);
            Rgb acc{0, 0, 0};
            addScaled(acc, bilinearSample(img, px, py, wrap), 4.0 / 8.0);
            for (int sy = -1; sy <= 1; sy += 2)
                for (int sx = -1; sx <= 1; sx += 2)
                    addScaled(acc, bilinearSample(img, px + sx * hp, py + sy * hp, wrap), 1.0 / 8.0);
            store(out, x, y, acc);
        }
    }
    return out;
}

// Bjorge 2015, dual filter upsample.
RgbImage kawaseUp(const RgbImage& small, int w, int h, double offset, Wrap wrap) {
    const double hp = 0.5 * offset;
    RgbImage out(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double px = sourcePos(x, w, small.width), py = sourcePos(y, h, small.height);
            auto s = [&](double dx, double dy) { return bilinearSample(small, px + dx, py + dy, wrap); };
            Rgb acc{0, 0, 0};
            addScaled(acc, s(-2 * hp, 0), 1.0 / 12.0);
            addScaled(acc, s(2 * hp, 0), 1.0 / 12.0);
            addScaled(acc, s(0, -2 * hp), 1.0 / 12.0);
            addScaled(acc, s(0, 2 * hp), 1.0 / 12.0);
            addScaled(acc, s(-hp, -hp), 2.0 / 12.0);
            addScaled(acc, s(hp, -hp), 2.0 / 12.0);
            addScaled(acc, s(-hp, hp), 2.0 / 12.0);
            addScaled(acc, s(hp, hp), 2.0 / 12.0);
            store(out, x, y, acc);
        }
    }
    return out;
}

RgbImage dualKawaseBlur(const RgbImage& img, int iterations, double offset, Wrap wrap) {
    if (iterations < 1) return img;
    std::vector<RgbImage> chain{img};
    for (int k = 0; k < iterations; ++k) chain.push_back(kawaseDown(chain.back(), offset, wrap));
    RgbImage cur = chain.back();
    for (int k = iterations - 1; k >= 0; --k)
        cur = kawaseUp(cur, chain[size_t(k)].width, chain[size_t(k)].height, offset, wrap);
    return cur;
}

}  // namespace glimmer
