// The page's "Measure blurs on this machine" (issue 27, the lesson's
// minutes 30 to 38): `glimmer tradeoff`'s measuring (bloom/tradeoff_run.h,
// the same code) on the page's WebGL 2 context, on the student's own GPU.
// The page steps it, one piece of work per animation frame, so it keeps
// painting and taking input while the methods run:
//   glimmer_tradeoff_start(width, height, repeat, words) -> how many methods
//       will run (those whose name holds one of the space-separated words),
//       or -1 with the reason in glimmer_last_output(). The input is the
//       project's grid picture at width x height, the targets RGBA16F, as
//       `glimmer tradeoff --size WxH --methods WORDS --repeat N`.
//   glimmer_tradeoff_step() -> 1 while there is more to do, 0 once every
//       method is measured, -1 when a method could not run (its diagnostics
//       in glimmer_last_output()). Each call is one piece: a method prepared,
//       a part of its warm-up, one timed run, or its read-back and CPU
//       references (the longest: superblur h11's reference, 529 taps a
//       pixel in doubles, about half a second here).
//   glimmer_tradeoff_status() -> what the last step did, "3/12 superblur h11: run 2 of 5".
//   glimmer_tradeoff_rows() -> the rows so far as JSON (see rowsJson).
// Timing: WebGL's finish() returns before Chromium's GPU process has drawn
// anything, so each run is the wall clock between two reads of one pixel of
// the method's own target: a read returns only once every command before it
// has run. That read's round trip is in every run, so times are upper bounds.
#include <emscripten/emscripten.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bloom/tradeoff_run.h"
#include "gl/renderer.h"
#include "image/test_images.h"
#include "pipeline/console.h"
#include "web/page_state.h"

namespace {

using namespace glimmer;

// Where the input picture and each method's script are written in the
// module's file system; the kernel files come with the bundled lesson.
constexpr const char* kFolder = "/tmp/glimmer-tradeoff";
constexpr const char* kBundledLesson = "/lesson";
// The desktop's warm-up on a CPU renderer (200 ms, app/tradeoff_command.cpp),
// given in frames of at most about 100 ms each (at least one draw each).
constexpr auto kWarmUpStep = std::chrono::milliseconds(100);
constexpr int kWarmUpSteps = 2;
// Each timed run renders for at least this long (TradeoffSettings::minRun):
// Firefox's and WebKit's performance.now() tick in whole milliseconds
// without cross-origin isolation, so a 0.3 ms blur timed once read 0 or 1;
// over 25 ms the tick is at most 4% of the figure. One run is still one
// animation frame.
constexpr auto kMinRun = std::chrono::milliseconds(25);

// One measuring run of the page, from start to its last row.
struct Run {
    std::unique_ptr<Renderer> renderer;  // of its own, on the page's context: the live view's is left alone
    std::string rendererName;            // GL_RENDERER (the browser's; WebGL masks the GPU's own name)
    TradeoffInput input;
    TradeoffSettings settings;
    std::vector<BlurMethod> methods;
    std::vector<TradeoffRow> rows;
    std::unique_ptr<BlurMeasurement> current;  // the method being measured
    int warmUps = 0;                            // warm-up steps current has had
    std::string status;
};
std::unique_ptr<Run> run;

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", int(c));
        else out += c;
    }
    return out + "\"";
}

// Finite numbers only: PSNR of identical pictures is infinite, which JSON cannot say.
std::string jsonNumber(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "null"; }

// {"renderer", "width", "height", "format", "repeat", "min_run_ms", "methods": [{"method",
// "family", "taps", "ms", "min", "max", "runs", "renders_per_run", "sigma", "numerical":
// {"rmse", "psnr", "max", "over_one_step"}, "model": {...}, "healthy"}],
// "fastest": {"methods": [...], "clear_winner", "candidates"}}: the
// desktop's PREFIX.json, less what the page does not measure (the floor).
std::string rowsJson() {
    if (!run) return "{}";
    auto errors = [](const ErrorStats& e) {
        return fmt::format(R"({{"rmse": {}, "psnr": {}, "max": {}, "over_one_step": {}}})", jsonNumber(e.rmse),
                           jsonNumber(e.psnr), jsonNumber(e.maxAbs), e.pixelsOverOneStep);
    };
    std::ostringstream out;
    out << fmt::format(R"({{"renderer": {}, "width": {}, "height": {}, "format": {}, "repeat": {}, "min_run_ms": {}, )"
                       R"("methods": [)",
                       jsonString(run->rendererName), run->input.image.width,
                       run->input.image.height, jsonString(textureFormatName(run->settings.format)),
                       run->settings.repeat, run->settings.minRun.count());
    for (std::size_t i = 0; i < run->rows.size(); ++i) {
        const TradeoffRow& r = run->rows[i];
        out << (i ? ", " : "")
            << fmt::format(R"({{"method": {}, "family": {}, "taps": {}, "ms": {}, "min": {}, "max": {}, "runs": {}, )"
                           R"("renders_per_run": {}, "sigma": {}, "numerical": {}, "model": {}, "healthy": {}}})",
                           jsonString(r.method->name), jsonString(r.method->family), r.method->tapsPerPixel,
                           jsonNumber(r.ms), jsonNumber(r.time.min), jsonNumber(r.time.max), r.time.runs,
                           r.rendersPerRun, jsonNumber(r.sigma), errors(r.numerical), errors(r.model), r.health.healthy());
    }
    const std::vector<TimedCandidate> candidates = nearGaussianCandidates(run->rows);
    const FastestVerdict verdict = fastestBeyondNoise(candidates);
    out << R"(], "fastest": {"methods": [)";
    for (std::size_t i = 0; i < verdict.names.size(); ++i) out << (i ? ", " : "") << jsonString(verdict.names[i]);
    out << fmt::format(R"(], "clear_winner": {}, "candidates": {}, "near_gaussian_psnr": {}}}}})",
                       verdict.clearWinner(), candidates.size(), kNearGaussianPsnr);
    return out.str();
}

void fail(const std::string& why, const Diagnostics* diags = nullptr, const SourceTexts* sources = nullptr) {
    std::ostringstream out;
    if (diags) printDiagnostics(*diags, *sources, out);
    if (!why.empty()) out << "glimmer: error: " << why << "\n";
    glimmer_web::setLastOutput(out.str());
}

std::string lastJson;  // what glimmer_tradeoff_rows returned last: the page reads it as a C string

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE int glimmer_tradeoff_start(int width, int height, int repeat, const char* words) {
    run.reset();
    glimmer_web::setLastOutput("");
    if (width < 16 || height < 16 || width > 2048 || height > 2048 || repeat < 1 || repeat > 50) {
        fail("the size must be 16 to 2048 on each side and the runs 1 to 50");
        return -1;
    }
    std::string why;
    if (!glimmer_web::pageContext(&why)) {
        fail(why);
        return -1;
    }
    auto r = std::make_unique<Run>();
    r->renderer = Renderer::create([](const char* n) { return glimmer_web::pageContext()->getProcAddress(n); }, why);
    if (!r->renderer) {
        fail(why);
        return -1;
    }
    r->rendererName = r->renderer->rendererName();
    std::error_code ec;
    std::filesystem::create_directories(kFolder, ec);
    r->input.image = makeGridImage(width, height);
    r->input.rgb = toRgb(r->input.image);
    r->input.path = std::string(kFolder) + "/input.bmp";
    if (!writeBmp(r->input.path, r->input.image, why)) {
        fail(why);
        return -1;
    }
    std::istringstream list(words ? words : "");
    std::vector<std::string> wanted;
    for (std::string w; list >> w;) wanted.push_back(w);
    r->methods = methodsNamed(blurMethods(), wanted);
    if (r->methods.empty()) {
        fail(fmt::format("no method's name holds any of '{}'", words ? words : ""));
        return -1;
    }
    r->settings.repeat = repeat;
    r->settings.warmUp = kWarmUpStep;
    r->settings.folder = kFolder;
    r->settings.includeDirs = blurKernelDirs(kBundledLesson);
    r->settings.wallClock = true;
    r->settings.minRun = kMinRun;
    r->status = fmt::format("0/{}", r->methods.size());
    run = std::move(r);
    return int(run->methods.size());
}

EMSCRIPTEN_KEEPALIVE int glimmer_tradeoff_step() {
    if (!run || run->rows.size() == run->methods.size()) return 0;
    const std::size_t i = run->rows.size();
    const BlurMethod& m = run->methods[i];
    const std::string at = fmt::format("{}/{} {}", i + 1, run->methods.size(), m.name);
    if (!run->current) {
        run->current = std::make_unique<BlurMeasurement>(*run->renderer, run->input, m, run->settings);
        Diagnostics diags;
        if (!run->current->prepare(diags)) {
            fail("", &diags, &run->current->sources());
            run->status = at + ": could not run";
            run->current.reset();
            run->renderer.reset();
            return -1;
        }
        run->warmUps = 0;
        run->status = at + ": prepared";
        return 1;
    }
    if (run->warmUps < kWarmUpSteps) {
        run->current->warmUp();
        run->status = fmt::format("{}: warming up ({} of {})", at, ++run->warmUps, kWarmUpSteps);
        return 1;
    }
    if (run->current->runsTimed() < run->settings.repeat) {
        run->current->timeRun();
        run->status = fmt::format("{}: run {} of {}", at, run->current->runsTimed(), run->settings.repeat);
        return 1;
    }
    run->rows.push_back(run->current->result());
    run->current.reset();
    run->status = at + ": measured";
    if (run->rows.size() < run->methods.size()) return 1;
    // Done: the GL objects go, the rows stay for glimmer_tradeoff_rows.
    run->renderer.reset();
    return 0;
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_tradeoff_status() { return run ? run->status.c_str() : ""; }

EMSCRIPTEN_KEEPALIVE const char* glimmer_tradeoff_rows() {
    lastJson = rowsJson();
    return lastJson.c_str();
}

}  // extern "C"
