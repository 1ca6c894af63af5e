#include <chrono>
#include <charconv>
#include <iostream>

#include <fmt/format.h>

#include "driver/numeric_health.h"
#include "driver/session.h"
#include "image/image.h"

namespace glimmer {
namespace {

struct Dump {
    int unit = -1;
    std::string file;
};

bool parseDump(const std::string& text, Dump& d) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq + 1 >= text.size()) return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + eq, d.unit);
    d.file = text.substr(eq + 1);
    return ec == std::errc() && end == text.data() + eq && d.unit >= 0 && d.unit <= 31;
}

}  // namespace

int runRender(const RenderOptions& o) {
    using Clock = std::chrono::steady_clock;
    std::vector<Dump> dumps;
    std::set<int> keep;
    for (const auto& text : o.dumps) {
        Dump d;
        if (!parseDump(text, d)) {
            std::cerr << fmt::format("glimmer: error: --dump '{}' is not UNIT=FILE with a unit from 0 to 31\n", text);
            return kExitUsage;
        }
        dumps.push_back(d);
        keep.insert(d.unit);
    }
    Session s;
    if (auto code = openSession(o, keep, false, s)) return *code;
    // A unit with nothing on it is a typo: say so before drawing or writing anything.
    for (const auto& d : dumps) {
        if (!s.loaded.plan.finalUnits.count(d.unit)) {
            std::cerr << fmt::format("glimmer: error: --dump {}: no texture on unit {}\n", d.unit, d.unit);
            return kExitUsage;
        }
    }

    auto t0 = Clock::now();
    s.renderer->render(*s.values, o.time);
    Image screen = s.renderer->readScreen();
    auto t1 = Clock::now();
    std::string why;
    if (!writePng(o.output, screen, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    for (const auto& d : dumps) {
        auto it = s.loaded.plan.finalUnits.find(d.unit);
        Image img;
        if (it != s.loaded.plan.finalUnits.end())
            img = s.renderer->isFloatTexture(it->second) ? s.renderer->readTextureFloat(it->second)
                                                         : s.renderer->readTexture(it->second);
        if (img.empty()) {
            std::cerr << fmt::format("glimmer: error: --dump {}: no texture on unit {}\n", d.unit, d.unit);
            return kExitUsage;
        }
        if (!writeImage(d.file, img, why)) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitScriptError;
        }
    }
    auto t2 = Clock::now();
    bool bad = false;
    if (o.health || o.strict) {
        for (const auto& h : measureHealth(*s.renderer, s.loaded.plan)) {
            std::cerr << formatHealth(h) << "\n";
            bad |= h.bad();
        }
    }
    if (o.timings) {
        auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
        std::cerr << fmt::format("{} on {}: start-up {:.1f} ms, compile {:.1f} ms, render {:.1f} ms, write {:.1f} ms\n",
                                 s.context->name(), s.renderer->rendererName(), s.startupMs, s.compileMs, ms(t0, t1),
                                 ms(t1, t2));
    }
    if (o.strict && bad) {
        std::cerr << "glimmer: error: --strict: a target holds NaN, Inf, negative or out-of-range values\n";
        return kExitScriptError;
    }
    return kExitOk;
}

}  // namespace glimmer
