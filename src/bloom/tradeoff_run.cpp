#include "bloom/tradeoff_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "gl/renderer.h"
#include "pipeline/prepare_script.h"

namespace glimmer {
namespace {

// A run's renders at most, whatever TradeoffSettings::minRun asks.
constexpr int kMostRendersPerRun = 1000;

int bytesPerTexel(TextureDecl::Format f) {
    switch (f) {
    case TextureDecl::Format::RGBA8: return 4;
    case TextureDecl::Format::RGBA16F: return 8;
    case TextureDecl::Format::RGBA32F: return 16;
    case TextureDecl::Format::R11F_G11F_B10F: return 4;
    }
    return 4;
}

}  // namespace

BlurMeasurement::BlurMeasurement(Renderer& renderer, const TradeoffInput& input, const BlurMethod& method,
                                 const TradeoffSettings& settings)
    : renderer_(renderer), input_(input), method_(method), settings_(settings) {}

bool BlurMeasurement::prepare(Diagnostics& diags) {
    const std::filesystem::path script = std::filesystem::path(settings_.folder) / "method.glib";
    std::ofstream(script) << method_.script(input_.path, input_.image.width, input_.image.height,
                                            textureFormatName(settings_.format));
    ScriptRequest request;
    request.script = script.string();
    request.plan.keepTargets = {method_.outputUnit};
    request.plan.includeDirs = settings_.includeDirs;
    request.plan.width = input_.image.width;
    request.plan.height = input_.image.height;
    if (!prepareScript(request, renderer_, diags, loaded_)) return false;
    values_.emplace(loaded_.plan);
    outputTexture_ = loaded_.plan.finalUnits.at(method_.outputUnit);
    return true;
}

void BlurMeasurement::waitForGpu() const { renderer_.finish(outputTexture_); }

void BlurMeasurement::warmUp() {
    const auto warmStart = std::chrono::steady_clock::now();
    do {
        renderer_.render(*values_, 0);
        waitForGpu();
    } while (std::chrono::steady_clock::now() - warmStart < settings_.warmUp);
}

void BlurMeasurement::timeRun() {
    if (!settings_.wallClock) {
        std::vector<PassTiming> t;
        renderer_.render(*values_, 0, &t);
        double sum = 0;
        for (const auto& p : t) sum += p.ms;
        times_.push_back(sum);
        return;
    }
    // Nothing drawn before the run is the run's to pay for.
    waitForGpu();
    const auto start = std::chrono::steady_clock::now();
    const double atLeast = double(settings_.minRun.count());
    int renders = 0;
    double ms = 0;
    do {  // a bound on the renders too: a clock that does not move must not hang the page
        renderer_.render(*values_, 0);
        waitForGpu();
        ++renders;
        ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    } while (ms < atLeast && renders < kMostRendersPerRun);
    rendersPerRun_ = std::max(rendersPerRun_, renders);
    times_.push_back(ms / renders);
}

TradeoffRow BlurMeasurement::result() const {
    Image out = renderer_.readTextureFloat(outputTexture_);
    RgbImage gpu = toRgb(out);
    TradeoffRow row;
    row.method = &method_;
    row.health = healthOf(out.f32.data(), out.width, out.height);
    row.time = spreadOf(times_);
    row.ms = row.time.median;
    row.rendersPerRun = rendersPerRun_;
    row.numerical = compare(gpu, method_.reference(input_.rgb));
    row.sigma = impulseSigma(method_.reference);
    const int radius = int(std::ceil(4 * row.sigma));
    row.model = compare(gpu, gaussianBlur(input_.rgb, row.sigma, radius, Wrap::Repeat));
    const double texels = double(input_.image.width) * double(input_.image.height);
    row.megabytes = texels * (method_.tapsPerPixel + method_.texelsWrittenPerPixel) * bytesPerTexel(settings_.format) / 1e6;
    return row;
}

std::vector<TimedCandidate> nearGaussianCandidates(const std::vector<TradeoffRow>& rows) {
    std::vector<TimedCandidate> candidates;
    for (const auto& r : rows)
        if (r.model.psnr >= kNearGaussianPsnr) candidates.push_back({r.method->name, r.time});
    return candidates;
}

bool measureBlurMethods(Renderer& renderer, const TradeoffInput& input, const std::vector<BlurMethod>& methods,
                        const TradeoffSettings& settings,
                        const std::function<void(std::size_t i, std::size_t count, const BlurMethod&)>& progress,
                        std::vector<TradeoffRow>& rows, Diagnostics& diags, SourceTexts& sources) {
    for (std::size_t i = 0; i < methods.size(); ++i) {
        if (progress) progress(i, methods.size(), methods[i]);
        BlurMeasurement m(renderer, input, methods[i], settings);
        if (!m.prepare(diags)) {
            sources = m.sources();
            return false;
        }
        m.warmUp();
        for (int r = 0; r < settings.repeat; ++r) m.timeRun();
        rows.push_back(m.result());
    }
    return true;
}

}  // namespace glimmer
