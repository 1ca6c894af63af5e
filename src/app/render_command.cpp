#include <chrono>
#include <charconv>
#include <cmath>
#include <optional>
#include <iostream>

#include <fmt/format.h>

#include "app/subcommands.h"
#include "pipeline/console.h"
#include "pipeline/numeric_health.h"
#include "process/output_guard.h"
#include "process/test_fault.h"
#include "process/session.h"
#include "image/animation.h"
#include "image/image.h"
#include "image/png_stream.h"

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

// Where the pictures go: one PNG, standard output, numbered PNGs, or an
// animated WebP.
struct Output {
    enum class Kind { Png, Stdout, Pattern, Webp };
    Kind kind = Kind::Png;
};

std::optional<int> chooseOutput(const RenderOptions& o, Output& out) {
    if (o.frames < 1 || !(o.fps > 0) || !std::isfinite(o.fps)) {
        std::cerr << fmt::format("glimmer: error: --frames {} --fps {:g}: --frames must be 1 or more and --fps more "
                                 "than 0\n", o.frames, o.fps);
        return kExitUsage;
    }
    if (o.pngLevel < 0 || o.pngLevel > 9) {
        std::cerr << fmt::format("glimmer: error: --png-level {} is not between 0 and 9\n", o.pngLevel);
        return kExitUsage;
    }
    std::string lower = o.output;
    for (auto& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    std::string why, name;
    if (o.output == "-") out.kind = Output::Kind::Stdout;
    else if (isFramePattern(o.output)) out.kind = Output::Kind::Pattern;
    else if (lower.size() > 5 && lower.compare(lower.size() - 5, 5, ".webp") == 0) out.kind = Output::Kind::Webp;
    if (out.kind == Output::Kind::Pattern && !frameFileName(o.output, 0, name, why)) {
        std::cerr << "glimmer: error: -o " << why << "\n";
        return kExitUsage;
    }
    if (o.frames > 1 && (out.kind == Output::Kind::Png || out.kind == Output::Kind::Stdout)) {
        std::cerr << fmt::format("glimmer: error: --frames {} writes several pictures: give -o a frame pattern such "
                                 "as frame_%04d.png, or an animated .webp\n", o.frames);
        return kExitUsage;
    }
    return std::nullopt;
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
    Output out;
    if (auto code = chooseOutput(o, out)) return *code;
    if (auto code = checkWatchOptions(o)) return *code;
    Session s;
    if (auto code = openSession(o, keep, false, s)) return *code;
    // A unit with nothing on it is a typo: say so before drawing or writing anything.
    for (const auto& d : dumps) {
        if (!s.loaded.plan.finalUnits.count(d.unit)) {
            std::cerr << fmt::format("glimmer: error: --dump {}: no texture on unit {}\n", d.unit, d.unit);
            return kExitUsage;
        }
    }

    // Never over one of the script's own files (process/output_guard.h).
    std::vector<std::pair<std::string, std::string>> outputs;  // option, file
    // Every kind but standard output: a frame pattern's every frame, and a
    // watch's file (written by its name as given; issue 37).
    if (out.kind != Output::Kind::Stdout) outputs.push_back({"-o", o.output});
    for (const auto& d : dumps) outputs.push_back({fmt::format("--dump {}", d.unit), d.file});
    for (const auto& [option, file] : outputs) {
        if (std::string refusal = overwritesAnInput(s.loaded.plan, option, file, "picture", std::max(1, o.frames));
            !refusal.empty()) {
            std::cerr << refusal;
            return kExitUsage;
        }
    }

    if (!o.watch.empty()) return runRenderWatch(o, s);

    auto t0 = Clock::now();
    Clock::duration writing{};  // the PNGs' share of the loop, reported as "write" with the dumps
    std::vector<Image> frames;  // for an animated file
    std::string why, first, last;
    // A call the driver refused did nothing, and nothing else says so
    // (gl/gl_api.h): the first, warned once after every frame.
    std::string refused;
    Progress progress;
    for (int i = 0; i < o.frames; ++i) {
        s.renderer->render(*s.values, o.time + double(i) / o.fps);
        Image screen = s.renderer->readScreen();
        // A lost or reset context reads back what it reads (zeros on
        // NVIDIA): no file of it, an error that says why, as batch does.
        // Asked after the read, which has already waited for the frame.
        std::string refusedNow;
        const std::string failure = pictureFailure(*s.renderer, o.script, screen, &refusedNow);
        if (refused.empty()) refused = refusedNow;
        if (!failure.empty()) {
            progress.finish();
            std::cerr << "glimmer: error: " << failure << "\n";
            return kExitScriptError;
        }
        bool ok = true;
        const auto tw = Clock::now();
        if (out.kind == Output::Kind::Stdout) {
            ok = writePngToStdout(screen, why, o.pngLevel);
        } else if (out.kind == Output::Kind::Pattern) {
            std::string name;
            ok = frameFileName(o.output, i, name, why) && writePng(name, screen, why, o.pngLevel);
            (i == 0 ? first : last) = name;
        } else if (out.kind == Output::Kind::Webp) {
            frames.push_back(std::move(screen));
        } else {
            ok = writePng(o.output, screen, why, o.pngLevel);
        }
        writing += Clock::now() - tw;
        if (!ok) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitScriptError;
        }
        if (o.frames > 1) progress.update(fmt::format("render: frame {}/{}", i + 1, o.frames));
    }
    progress.finish();
    printWarning(std::cerr, refused);
    const auto tw = Clock::now();
    if (out.kind == Output::Kind::Webp && !writeAnimatedWebp(o.output, frames, o.fps, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    auto t1 = Clock::now();
    writing += t1 - tw;
    std::string wrote;
    const int w = s.loaded.plan.width, h = s.loaded.plan.height;
    switch (out.kind) {
    case Output::Kind::Stdout: wrote = fmt::format("a {}x{} PNG to standard output", w, h); break;
    case Output::Kind::Png: wrote = fmt::format("{} ({}x{})", o.output, w, h); break;
    case Output::Kind::Pattern:
        wrote = o.frames == 1 ? fmt::format("{} ({}x{})", first, w, h)
                              : fmt::format("{} frames, {} to {} ({}x{}, {:g} fps)", o.frames, first, last, w, h, o.fps);
        break;
    case Output::Kind::Webp:
        wrote = fmt::format("{} ({} frame{}, {}x{}, {:g} fps)", o.output, o.frames, o.frames == 1 ? "" : "s", w, h, o.fps);
        break;
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
        wrote += fmt::format(", {} (unit {})", d.file, d.unit);
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
                                 s.context->name(), s.renderer->rendererName(), s.startupMs, s.compileMs,
                                 ms(t0, t1 - writing), ms(t1 - writing, t2));
    }
    reportWrote(wrote);
    if (o.strict && bad) {
        std::cerr << "glimmer: error: --strict: a target holds NaN, Inf, negative or out-of-range values\n";
        return kExitScriptError;
    }
    return kExitOk;
}

}  // namespace glimmer
