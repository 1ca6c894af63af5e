// The measuring of `glimmer tradeoff`, apart from its command line so the
// page runs the same code on the student's own machine (issue 27): for each
// blur method, its script written and prepared on a renderer, warmed up,
// timed `repeat` times, its float target read back and compared with the
// method's double-precision CPU reference (numerical error) and an exact
// Gaussian of the same sigma (model error). Portable: the page builds it.
//
// One method is measured in steps (BlurMeasurement) so the page can give
// each step an animation frame of its own and keep answering; the desktop
// runs them back to back (measureBlurMethods).
#pragma once
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bloom/blur_methods.h"
#include "bloom/timing_verdict.h"
#include "image/image.h"
#include "lang/diagnostics.h"
#include "metrics/metrics.h"
#include "metrics/rgb_image.h"
#include "pipeline/load_script.h"
#include "plan/uniform_values.h"

namespace glimmer {

class Renderer;

struct TradeoffRow {
    const BlurMethod* method = nullptr;
    double ms = 0;      // the median run
    TimingSpread time;  // every run: median, fastest, slowest
    double sigma = 0;   // the method's own impulse sigma (achieved, under --match-sigma)
    double megabytes = 0;
    // The texel-rate floor for the method's taps: taps per pixel times the
    // hand-written probe's time per tap (Renderer::texelRateMs: its fastest
    // run; same run, format and size); 0 when the probe could not run (or
    // was not asked for: the page has none). The table's min/flr compares
    // the method's fastest run with it: on a shared GPU, only the fastest
    // runs are free of other work.
    double floorMs = 0;
    int rendersPerRun = 1;  // the most renders one timed run took (TradeoffSettings::minRun)
    ErrorStats numerical, model;
    Health health;  // of the blurred target: NaN, Inf, negative, above 65504
};

// The picture every method blurs, in the three forms the run needs.
struct TradeoffInput {
    Image image;       // as the GPU reads it
    RgbImage rgb;      // the same in doubles, what the CPU references blur
    std::string path;  // a file holding it, which each method's script names
};

struct TradeoffSettings {
    TextureDecl::Format format = TextureDecl::Format::RGBA16F;
    int repeat = 5;  // timed runs per method, after the warm-up
    // Drawn for this long before the timed runs, at least once: llvmpipe
    // compiles shaders at first draw, and a GPU left idle while the CPU
    // references ran has lowered its clocks.
    std::chrono::milliseconds warmUp{200};
    std::string folder;                    // where each method's script is written (method.glib)
    std::vector<std::string> includeDirs;  // the kernel files' folders: blurKernelDirs(dataDir)
    // False (the desktop): each run is the sum of render()'s pass timings,
    // GPU timer queries or glFinish and a wall clock. True (the page): a run
    // is the wall clock around the whole render(), from one
    // Renderer::finish(output) to the next (in the browser that waits for
    // the output target itself, WebGL's own finish() does not wait).
    bool wallClock = false;
    // With wallClock, a run renders again until this much wall clock has
    // passed and reads as the total over its renders: the page's clock may
    // tick in whole milliseconds (Firefox, WebKit), which made every blur of
    // under a millisecond read 0 or 1 and five methods tie (issue 39).
    std::chrono::milliseconds minRun{0};
};

// One method on one renderer: prepare, warmUp, timeRun (repeat times),
// result, in that order; each may be called in a frame of its own.
class BlurMeasurement {
public:
    BlurMeasurement(Renderer& renderer, const TradeoffInput& input, const BlurMethod& method,
                    const TradeoffSettings& settings);
    // Writes the method's script into settings.folder and prepares it on the
    // renderer. False with diagnostics (sources() names their files) when it
    // cannot run: a kernel file missing, a target format the context lacks.
    bool prepare(Diagnostics& diags);
    void warmUp();
    void timeRun();
    int runsTimed() const { return int(times_.size()); }
    // Reads the method's target back and compares it with the references
    // (the CPU's share of the work: on a 256x256 picture, superblur h11's
    // reference is 529 taps a pixel in doubles).
    TradeoffRow result() const;
    const SourceTexts& sources() const { return loaded_.sources; }

private:
    void waitForGpu() const;
    Renderer& renderer_;
    const TradeoffInput& input_;
    const BlurMethod& method_;
    const TradeoffSettings& settings_;
    LoadedScript loaded_;
    std::optional<UniformValues> values_;  // once prepared (it is made from the plan)
    int outputTexture_ = -1;
    std::vector<double> times_;
    int rendersPerRun_ = 1;
};

// The verdict's candidates: a method far from a Gaussian is not one however
// fast it is, so only those within kNearGaussianPsnr dB of the Gaussian of
// their own sigma; fastestBeyondNoise (bloom/timing_verdict.h) picks among them.
constexpr double kNearGaussianPsnr = 40;
std::vector<TimedCandidate> nearGaussianCandidates(const std::vector<TradeoffRow>& rows);

// Every method in turn, `progress(i, count, method)` before each. False at
// the first that cannot run, its diagnostics in `diags` and the files they
// name in `sources`; `rows` then holds the methods before it.
bool measureBlurMethods(Renderer& renderer, const TradeoffInput& input, const std::vector<BlurMethod>& methods,
                        const TradeoffSettings& settings,
                        const std::function<void(std::size_t i, std::size_t count, const BlurMethod&)>& progress,
                        std::vector<TradeoffRow>& rows, Diagnostics& diags, SourceTexts& sources);

}  // namespace glimmer
