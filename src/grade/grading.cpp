#include "grade/grading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "metrics/metrics.h"
#include "metrics/ssim.h"

namespace glimmer {

std::vector<Setting> settingsFromSliders(const std::vector<Slider>& sliders, size_t maxSettings) {
    std::vector<Setting> out{Setting{}};
    for (const auto& s : sliders) {
        std::set<double> seen{s.value};
        for (double v : {s.min, s.max}) {
            if (out.size() >= maxSettings) return out;
            if (!seen.insert(v).second) continue;
            out.push_back({fmt::format("{}={:g}", s.name, v)});
        }
    }
    return out;
}

bool settingsFromVary(const std::vector<std::string>& vary, std::vector<Setting>& out, std::string& error) {
    out = {Setting{}};
    for (const auto& text : vary) {
        auto eq = text.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 >= text.size()) {
            error = fmt::format("--vary '{}' is not NAME=V1,V2,...", text);
            return false;
        }
        std::stringstream ss(text.substr(eq + 1));
        int n = 0;
        for (std::string v; std::getline(ss, v, ',');)
            if (!v.empty()) out.push_back({text.substr(0, eq) + "=" + v}), ++n;
        if (n == 0) {
            error = fmt::format("--vary '{}' gives no values", text);
            return false;
        }
    }
    if (out.size() > 64) {
        error = fmt::format("--vary gives {} settings; at most 64", out.size());
        return false;
    }
    return true;
}

std::string settingLabel(const Setting& s) {
    if (s.empty()) return "defaults";
    std::string out;
    for (const auto& a : s) out += (out.empty() ? "" : ", ") + a;
    return out;
}

namespace {

std::vector<double> luma(const Image& p) {
    std::vector<double> out(size_t(p.width) * size_t(p.height));
    for (size_t t = 0; t < out.size(); ++t)
        out[t] = (0.299 * p.u8[t * 4] + 0.587 * p.u8[t * 4 + 1] + 0.114 * p.u8[t * 4 + 2]) / 255.0;
    return out;
}

RgbImage rgbOf(const Image& p) {
    RgbImage out(p.width, p.height);
    for (size_t t = 0; t < size_t(p.width) * size_t(p.height); ++t)
        for (size_t c = 0; c < 3; ++c) out.rgb[t * 3 + c] = p.u8[t * 4 + c] / 255.0;
    return out;
}

bool oneColour(const Image& p) {
    for (size_t t = 1; t < size_t(p.width) * size_t(p.height); ++t)
        for (size_t c = 0; c < 3; ++c)
            if (p.u8[t * 4 + c] != p.u8[c]) return false;
    return true;
}

bool comparable(const Image& student, const Image& solution) {
    return student.width == solution.width && student.height == solution.height && student.type == Image::Type::U8 &&
           solution.type == Image::Type::U8 && !student.empty();
}

}  // namespace

bool blankAgainst(const Image& student, const Image& solution) {
    return comparable(student, solution) && oneColour(student) && !oneColour(solution);
}

Comparison comparePictures(const Image& student, const Image& solution) {
    Comparison c;
    if (!comparable(student, solution)) return c;
    c.psnr = compare(rgbOf(student), rgbOf(solution)).psnr;
    c.ssim = ssim(luma(student), luma(solution), student.width, student.height, 8);
    c.blank = blankAgainst(student, solution);
    // The local measures: pixels clearly off, and the worst tile.
    size_t off = 0;
    const size_t n = size_t(student.width) * size_t(student.height);
    for (size_t t = 0; t < n; ++t)
        for (size_t ch = 0; ch < 3; ++ch)
            if (std::abs(int(student.u8[t * 4 + ch]) - int(solution.u8[t * 4 + ch])) > kLocalLevels) {
                ++off;
                break;
            }
    c.offShare = double(off) / double(n);
    const std::vector<double> ls = luma(student), lr = luma(solution);
    c.worstTile = 1;
    for (int ty = 0; ty < student.height; ty += kTileSide)
        for (int tx = 0; tx < student.width; tx += kTileSide) {
            const int w = std::min(kTileSide, student.width - tx), h = std::min(kTileSide, student.height - ty);
            std::vector<double> a(size_t(w) * size_t(h)), b(a.size());
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const size_t from = size_t(ty + y) * size_t(student.width) + size_t(tx + x);
                    a[size_t(y) * size_t(w) + size_t(x)] = ls[from];
                    b[size_t(y) * size_t(w) + size_t(x)] = lr[from];
                }
            c.worstTile = std::min(c.worstTile, ssim(a, b, w, h, 8));
        }
    return c;
}

Image differencePicture(const Image& student, const Image& solution) {
    Image d = Image::rgba8(solution.width, solution.height);
    const bool same = student.width == solution.width && student.height == solution.height;
    for (size_t t = 0; t < size_t(d.width) * size_t(d.height); ++t) {
        for (size_t c = 0; c < 3; ++c) {
            int diff = same ? std::abs(int(student.u8[t * 4 + c]) - int(solution.u8[t * 4 + c])) : 255;
            d.u8[t * 4 + c] = std::uint8_t(std::min(255, diff * 4));
        }
        d.u8[t * 4 + 3] = 255;
    }
    return d;
}

Image thumbnail(const Image& p, int maxSide) {
    const int side = std::max(p.width, p.height);
    if (side <= maxSide || p.empty()) return p;
    const int w = std::max(1, p.width * maxSide / side), h = std::max(1, p.height * maxSide / side);
    Image t = Image::rgba8(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int x0 = x * p.width / w, x1 = std::max(x0 + 1, (x + 1) * p.width / w);
            const int y0 = y * p.height / h, y1 = std::max(y0 + 1, (y + 1) * p.height / h);
            for (int c = 0; c < 4; ++c) {
                unsigned sum = 0;
                for (int yy = y0; yy < y1; ++yy)
                    for (int xx = x0; xx < x1; ++xx) sum += p.u8[(size_t(yy) * size_t(p.width) + size_t(xx)) * 4 + size_t(c)];
                t.u8[(size_t(y) * size_t(w) + size_t(x)) * 4 + size_t(c)] = std::uint8_t(sum / unsigned((x1 - x0) * (y1 - y0)));
            }
        }
    return t;
}

Verdict judge(const std::vector<Comparison>& perSetting, const std::vector<std::string>& missing, const Thresholds& t,
              size_t& worst) {
    Verdict v;
    worst = 0;
    if (perSetting.empty()) {
        v.kind = "error";
        v.notes = "no picture to compare";
        return v;
    }
    double minPsnr = std::numeric_limits<double>::infinity();
    bool blank = false;
    size_t mostOff = 0, worstTile = 0;
    for (size_t k = 0; k < perSetting.size(); ++k) {
        if (perSetting[k].ssim < perSetting[worst].ssim) worst = k;
        if (perSetting[k].offShare > perSetting[mostOff].offShare) mostOff = k;
        if (perSetting[k].worstTile < perSetting[worstTile].worstTile) worstTile = k;
        minPsnr = std::min(minPsnr, perSetting[k].psnr);
        blank |= perSetting[k].blank;
    }
    const bool localError = perSetting[mostOff].offShare > t.passOffShare || perSetting[worstTile].worstTile < t.passTileSsim;
    const double minSsim = perSetting[worst].ssim;
    v.score = int(std::lround(100 * std::clamp(minSsim, 0.0, 1.0)));
    std::vector<std::string> notes;
    if (blank) notes.push_back("the picture is a single colour");
    if (!missing.empty()) {
        std::string names;
        for (const auto& m : missing) names += (names.empty() ? "" : ", ") + m;
        notes.push_back("lacks the solution's uniform" + std::string(missing.size() > 1 ? "s " : " ") + names);
    }
    if (minSsim >= t.passSsim && minPsnr >= t.passPsnr && localError) {
        // Alike on the whole, wrong in a place: a person looks (the worst setting shown is that one).
        v.kind = "look";
        worst = perSetting[mostOff].offShare > t.passOffShare ? mostOff : worstTile;
        notes.push_back(fmt::format("a local error: {:.2f}% of the pixels off by more than {} levels, the worst "
                                    "{}x{} tile at SSIM {:.3f}",
                                    100 * perSetting[worst].offShare, kLocalLevels, kTileSide, kTileSide,
                                    perSetting[worst].worstTile));
    } else if (minSsim >= t.passSsim && minPsnr >= t.passPsnr) v.kind = missing.empty() ? "pass" : "look";
    else if (minSsim >= t.lookSsim && minPsnr >= t.lookPsnr && !blank) v.kind = "look";
    else v.kind = "wrong";
    if (v.kind != "pass" && notes.empty())
        notes.push_back(fmt::format("SSIM {:.3f}, PSNR {:.1f} dB at the worst setting", minSsim, minPsnr));
    for (const auto& n : notes) v.notes += (v.notes.empty() ? "" : "; ") + n;
    return v;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* const k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const unsigned b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0, b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const unsigned n = (b0 << 16) | (b1 << 8) | b2;
        out += k[(n >> 18) & 63];
        out += k[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? k[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k[n & 63] : '=';
    }
    return out;
}

}  // namespace glimmer
