// glimmer tradeoff: for each blur method, the time of its passes against its
// error: numerical (against a double-precision CPU reference of the same
// kernel) and model (against an exact Gaussian of the same sigma). Prints a
// table, writes CSV, JSON and a Pareto chart. Times are kept for every run:
// the median places a method, its fastest and slowest run say how much a
// difference between two methods can be trusted (bloom/timing_verdict.h).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/subcommands.h"
#include "app/tradeoff_report.h"
#include "backends/context.h"
#include "bloom/blur_methods.h"
#include "bloom/tradeoff_run.h"
#include "pipeline/console.h"
#include "process/data_dir.h"
#include "pipeline/prepare_script.h"
#include "pipeline/stats.h"
#include "gl/renderer.h"
#include "image/test_images.h"
#include "metrics/metrics.h"
#include "bloom/pareto_chart.h"
#include "util/temp_dir.h"

namespace fs = std::filesystem;

namespace glimmer {

// How long each method (and the floor probe) is drawn before it is timed. A
// GPU lowers its clocks while the CPU references run (the lent H100 idles at
// 345 MHz of 1980: the same pass then takes 5.7 times as long) and needs
// sustained work to raise them again; a CPU renderer only compiles at first draw.
constexpr auto kWarmUpGpu = std::chrono::milliseconds(1000), kWarmUpCpu = std::chrono::milliseconds(200);

void addTradeoffCommand(CLI::App& app, TradeoffOptions& o) {
    CLI::App* sub = app.add_subcommand("tradeoff", "time blur methods against their error; table, CSV, JSON, chart");
    sub->add_option("image", o.image, "input picture, or a .glib script whose picture is blurred (default: the "
                                      "project's grid pattern, generated at --size)");
    sub->add_option("--size", o.size, "size of the generated input WxH (default 512x512)");
    sub->add_option("--format", o.format, "target format: RGBA8, RGBA16F (default), RGBA32F, R11F_G11F_B10F");
    sub->add_option("--repeat", o.repeat, "timed runs per method after one warm-up (default 5)")->check(CLI::Range(1, 100000));
    sub->add_option("--methods", o.methods, "only methods whose name contains one of these words");
    addBackendOption(sub, o.backend);
    sub->add_option("--match-sigma", o.matchSigma,
                    "compare at one blur width: each family (superblur, sep9, linear5, dual Kawase) scaled to the "
                    "parameter whose sigma comes nearest S (0.5 to 16); the sigma column says how near (default: "
                    "every method at its natural width)")
        ->type_name("S");
    sub->add_option("-o,--output", o.output, "prefix of the files written: PREFIX.csv, .json, .png");
}

int runTradeoff(const TradeoffOptions& o) {
    TextureDecl::Format format;
    if (!parseTextureFormat(o.format, format)) {
        std::cerr << fmt::format("glimmer: error: --format '{}' is not RGBA8, RGBA16F, RGBA32F or R11F_G11F_B10F\n", o.format);
        return kExitUsage;
    }
    BackendChoice backend;
    if (!parseBackend(o.backend, backend) || o.repeat < 1) {  // refused as read (addBackendOption, Range)
        std::cerr << "glimmer: error: --backend or --repeat is not valid\n";
        return kExitUsage;
    }
    const bool matched = o.matchSigma != 0;
    if (matched && !(o.matchSigma >= 0.5 && o.matchSigma <= 16)) {
        // Above 16 the 128-texel impulse that measures sigma wraps round.
        std::cerr << fmt::format("glimmer: error: --match-sigma {:g} is not between 0.5 and 16\n", o.matchSigma);
        return kExitUsage;
    }
    // The input, as the GPU will see it.
    TempDir temp("glimmer-tradeoff");  // the input picture and each method's script; removed on every return
    const fs::path& dir = temp.path();
    Image input;
    std::string why;
    std::string imagePath;
    auto context = createContext(backend, why);
    if (!context) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    auto renderer = Renderer::create([&](const char* n) { return context->getProcAddress(n); }, why);
    if (!renderer) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    bool isScript = o.image.size() > 5 && o.image.compare(o.image.size() - 5, 5, ".glib") == 0;
    if (isScript) {
        // A script's picture as the input: what its screen shows, at --size
        // or its own size, blurred by each method.
        Diagnostics diags;
        LoadedScript loaded;
        ScriptRequest request;
        request.script = o.image;
        if (!o.size.empty() && !parseSize(o.size, request.plan.width, request.plan.height)) {
            std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT\n", o.size);
            return kExitUsage;
        }
        if (!prepareScript(request, *renderer, diags, loaded)) {
            printDiagnostics(diags, loaded.sources, std::cerr);
            return kExitScriptError;
        }
        renderer->render(UniformValues(loaded.plan), 0);
        input = renderer->readScreen();
        imagePath = (dir / "input.bmp").string();
        if (!writeBmp(imagePath, input, why)) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitScriptError;
        }
    } else if (!o.image.empty()) {
        if (!loadImage(o.image, input, why)) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitUsage;
        }
        imagePath = fs::absolute(o.image).string();
    } else {
        int w = 512, h = 512;
        if (!o.size.empty() && !parseSize(o.size, w, h)) {
            std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT\n", o.size);
            return kExitUsage;
        }
        input = makeGridImage(w, h);
        imagePath = (dir / "input.bmp").string();
        if (!writeBmp(imagePath, input, why)) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitScriptError;
        }
    }
    const RgbImage in = toRgb(input);

    const std::vector<BlurMethod> methods =
        methodsNamed(matched ? blurMethodsMatched(o.matchSigma) : blurMethods(), o.methods);
    std::vector<TradeoffRow> rows;
    const auto warmUp = renderer->gpuTimers() ? kWarmUpGpu : kWarmUpCpu;
    TradeoffSettings settings;
    settings.format = format;
    settings.repeat = o.repeat;
    settings.warmUp = warmUp;
    settings.folder = dir.string();
    settings.includeDirs = blurKernelDirs(dataDir());
    const TradeoffInput tradeoffInput{input, in, imagePath};
    Progress progress;
    Diagnostics diags;
    SourceTexts sources;
    if (!measureBlurMethods(
            *renderer, tradeoffInput, methods, settings,
            [&](size_t i, size_t n, const BlurMethod& m) {
                progress.update(fmt::format("tradeoff: {}/{} {}", i + 1, n, m.name));
            },
            rows, diags, sources)) {
        progress.finish();
        printDiagnostics(diags, sources, std::cerr);
        return kExitScriptError;
    }
    // The floor, measured in this run on this context: a hand-written pass of
    // 9 taps a pixel at the input's size and the targets' format.
    progress.update("tradeoff: the texel-rate floor");
    const double nineTapMs = renderer->texelRateMs(input.width, input.height, format, 9, std::max(o.repeat, 7), warmUp);
    progress.finish();
    if (nineTapMs > 0) {
        for (auto& r : rows) r.floorMs = nineTapMs / 9.0 * r.method->tapsPerPixel;
        fmt::print("texel-rate floor: {:.3f} ms for 9 taps a pixel, {:.2f} Gtexel/s (hand-written pass, fastest run, this run){}\n",
                   nineTapMs, 9.0 * input.width * input.height / (nineTapMs * 1e6),
                   renderer->gpuTimers() ? ""
                                         : "; on a CPU renderer shading, not fetching, sets the pace, so methods "
                                           "with few taps a pass can run under it");
    }

    // The header line says which comparison this is: each method at its
    // own width, or every family scaled to one sigma.
    double achievedLo = 0, achievedHi = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        achievedLo = i ? std::min(achievedLo, rows[i].sigma) : rows[i].sigma;
        achievedHi = i ? std::max(achievedHi, rows[i].sigma) : rows[i].sigma;
    }
    const std::string comparison =
        matched ? fmt::format("matched sigma = {:g} (achieved {:.2f} to {:.2f})", o.matchSigma, achievedLo, achievedHi)
                : "natural width";
    std::string title = fmt::format("{} on {}, {}x{} {}, median of {}, {}", context->name(), renderer->rendererName(),
                                    input.width, input.height, textureFormatName(format), o.repeat, comparison);
    fmt::print("{}\n", title);
    printTradeoffTable(rows);
    const FastestVerdict verdict = printTradeoffVerdict(rows, o.repeat);
    writeTradeoffCsv(o.output + ".csv", rows, matched ? o.matchSigma : 0);
    writeTradeoffJson(o.output + ".json", title, rows, verdict, matched ? o.matchSigma : 0);
    std::vector<ChartPoint> points;
    for (const auto& r : rows) points.push_back({r.method->name, r.ms, r.model.psnr, r.time.min, r.time.max});
    Image chart = paretoChart(
        points, fmt::format("PSNR against an exact Gaussian, by time: {}, {}x{} {}\n{}, median of {} runs", context->name(),
                            input.width, input.height, textureFormatName(format),
                            matched ? comparison + ", each family scaled to it"
                                    : "natural width (each method at its own sigma)",
                            o.repeat));
    if (!writePng(o.output + ".png", chart, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    reportWrote(fmt::format("{0}.csv, {0}.json, {0}.png", o.output));
    return kExitOk;
}

}  // namespace glimmer
