// The tradeoff's measuring (bloom/tradeoff_run.h), which `glimmer tradeoff`
// and the page both run: on a real renderer, at a tiny size, each method's
// row holds its own timings and errors, the page's way of timing (a wait
// on the method's target around each run) gives the same pixels, and a
// method that cannot run stops the loop with its diagnostics.
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "bloom/tradeoff_run.h"
#include "image/test_images.h"
#include "render_harness.h"

namespace fs = std::filesystem;
using namespace glimmer;
using namespace glimmer::testing;

namespace {

std::vector<BlurMethod> someMethods() {
    std::vector<BlurMethod> out;
    for (const auto& m : blurMethods())
        if (m.name == "superblur h1" || m.name == "sep9 x1" || m.name == "kawase x2") out.push_back(m);
    return out;
}

struct Fixture {
    fs::path dir;
    TradeoffInput input;
    TradeoffSettings settings;
    std::unique_ptr<GlContext> context;
    std::unique_ptr<Renderer> renderer;
    std::string why;

    explicit Fixture(const std::string& backend) {
        dir = fs::temp_directory_path() / ("glimmer_tradeoff_run_" + std::to_string(::getpid()));
        fs::create_directories(dir);
        input.image = makeGridImage(48, 32);
        input.rgb = toRgb(input.image);
        input.path = (dir / "input.bmp").string();
        EXPECT_TRUE(writeBmp(input.path, input.image, why)) << why;
        settings.repeat = 2;
        settings.warmUp = std::chrono::milliseconds(0);
        settings.folder = dir.string();
        settings.includeDirs = blurKernelDirs(GLIMMER_SOURCE_DIR);
        BackendChoice choice;
        EXPECT_TRUE(parseBackend(backend, choice)) << backend;
        context = createContext(choice, why);
        if (context) renderer = Renderer::create([&](const char* n) { return context->getProcAddress(n); }, why);
    }
    ~Fixture() { fs::remove_all(dir); }
};

}  // namespace

TEST(TradeoffRun, EachRowIsItsMethodsTimesAndErrors) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Fixture f(backend);
        ASSERT_TRUE(f.renderer) << "backend '" << backend << "' is unusable: " << f.why;
        const std::vector<BlurMethod> methods = someMethods();
        ASSERT_EQ(methods.size(), 3u);
        std::vector<std::string> announced;
        std::vector<TradeoffRow> rows;
        Diagnostics diags;
        SourceTexts sources;
        ASSERT_TRUE(measureBlurMethods(
            *f.renderer, f.input, methods, f.settings,
            [&](size_t i, size_t n, const BlurMethod& m) { announced.push_back(std::to_string(i) + "/" + std::to_string(n) + " " + m.name); },
            rows, diags, sources));
        EXPECT_EQ(announced, (std::vector<std::string>{"0/3 superblur h1", "1/3 sep9 x1", "2/3 kawase x2"}));
        ASSERT_EQ(rows.size(), 3u);
        for (size_t i = 0; i < rows.size(); ++i) {
            const TradeoffRow& r = rows[i];
            SCOPED_TRACE(methods[i].name);
            EXPECT_EQ(r.method, &methods[i]);
            EXPECT_EQ(r.time.runs, 2);
            EXPECT_GT(r.time.min, 0);
            EXPECT_LE(r.time.min, r.ms);
            EXPECT_LE(r.ms, r.time.max);
            EXPECT_DOUBLE_EQ(r.sigma, impulseSigma(methods[i].reference));
            // The GPU computes the same kernel as its CPU reference: RGBA16F
            // rounding only, never an 8-bit step; the model error (against
            // an exact Gaussian) is far larger, which is the lesson's point.
            EXPECT_EQ(r.numerical.pixelsOverOneStep, 0u);
            EXPECT_GT(r.numerical.psnr, 60);
            EXPECT_LT(r.model.psnr, r.numerical.psnr - 10);
            EXPECT_GT(r.model.psnr, 25);
            EXPECT_TRUE(r.health.healthy());
            EXPECT_EQ(r.floorMs, 0);  // the floor is the desktop command's, measured apart
            EXPECT_DOUBLE_EQ(r.megabytes, 48.0 * 32 * (methods[i].tapsPerPixel + methods[i].texelsWrittenPerPixel) * 8 / 1e6);
        }
    }
}

// The page times a run by the wall clock, waiting on the method's target
// before and after it (Renderer::finish(texture): WebGL's finish does not
// wait); the pixels, hence the errors, are those of the desktop's way.
TEST(TradeoffRun, WaitingOnTheTargetTimesTheSamePixels) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Fixture f(backend);
        ASSERT_TRUE(f.renderer) << "backend '" << backend << "' is unusable: " << f.why;
        const std::vector<BlurMethod> methods = someMethods();
        std::vector<TradeoffRow> plain, waited;
        Diagnostics diags;
        SourceTexts sources;
        ASSERT_TRUE(measureBlurMethods(*f.renderer, f.input, methods, f.settings, nullptr, plain, diags, sources));
        f.settings.wallClock = true;
        // One method at a time, as the page steps through them.
        for (const BlurMethod& m : methods) {
            BlurMeasurement one(*f.renderer, f.input, m, f.settings);
            ASSERT_TRUE(one.prepare(diags));
            one.warmUp();
            one.timeRun();
            one.timeRun();
            EXPECT_EQ(one.runsTimed(), 2);
            waited.push_back(one.result());
        }
        ASSERT_EQ(waited.size(), plain.size());
        for (size_t i = 0; i < plain.size(); ++i) {
            SCOPED_TRACE(methods[i].name);
            EXPECT_EQ(waited[i].numerical.rmse, plain[i].numerical.rmse);
            EXPECT_EQ(waited[i].model.rmse, plain[i].model.rmse);
            EXPECT_GT(waited[i].time.min, 0);
        }
    }
}

// The page's clock may tick in whole milliseconds, so a run there renders
// until TradeoffSettings::minRun has passed and reads as the time per
// render; without minRun a run is one render. The pixels are the same.
TEST(TradeoffRun, AWallClockRunRendersUntilItsMinimumHasPassed) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Fixture f(backend);
        ASSERT_TRUE(f.renderer) << "backend '" << backend << "' is unusable: " << f.why;
        f.settings.wallClock = true;
        BlurMethod sep9;
        for (const BlurMethod& m : someMethods())
            if (m.name == "sep9 x1") sep9 = m;
        ASSERT_EQ(sep9.name, "sep9 x1");
        Diagnostics diags;
        TradeoffRow once, long_;
        for (int minRun : {0, 60}) {
            f.settings.minRun = std::chrono::milliseconds(minRun);
            BlurMeasurement m(*f.renderer, f.input, sep9, f.settings);
            ASSERT_TRUE(m.prepare(diags));
            m.warmUp();
            m.timeRun();
            m.timeRun();
            EXPECT_EQ(m.runsTimed(), 2);
            (minRun ? long_ : once) = m.result();
        }
        EXPECT_EQ(once.rendersPerRun, 1);
        // A 48x32 9-tap blur takes well under 30 ms even on a loaded llvmpipe.
        EXPECT_GT(long_.rendersPerRun, 1);
        EXPECT_GT(long_.time.min, 0);
        EXPECT_EQ(long_.numerical.rmse, once.numerical.rmse);
    }
}

// A method whose kernel file cannot be found stops the run at that method:
// the rows before it kept, the error in the diagnostics with its file.
TEST(TradeoffRun, AMethodThatCannotRunStopsTheLoop) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Fixture f(backend);
        ASSERT_TRUE(f.renderer) << "backend '" << backend << "' is unusable: " << f.why;
        std::vector<BlurMethod> methods = someMethods();
        // kawase's kernels are in scripts/bloom; superblur's own is in shaders/.
        f.settings.includeDirs = {std::string(GLIMMER_SOURCE_DIR) + "/shaders"};
        std::vector<TradeoffRow> rows;
        Diagnostics diags;
        SourceTexts sources;
        EXPECT_FALSE(measureBlurMethods(*f.renderer, f.input, methods, f.settings, nullptr, rows, diags, sources));
        EXPECT_TRUE(diags.hasErrors());
        EXPECT_TRUE(rows.empty());  // superblur h1 also needs quad.vert, from scripts/bloom
        std::string printed;
        for (const auto& d : diags.all()) printed += formatDiagnostic(d, sources) + "\n";
        EXPECT_NE(printed.find("quad.vert"), std::string::npos) << printed;
        EXPECT_NE(printed.find("method.glib"), std::string::npos) << printed;
    }
}

// The texel-rate probe that `tradeoff` divides by (gl/texel_rate.cpp) takes
// what renderer.h promises, 1 to 1024 taps and 1 to 16384 pixels each way,
// and refuses the rest with -1 before it builds anything (issue 40: a sampled
// mutant that refused 1024 taps survived every test).
TEST(TexelRate, TheProbeRunsFromOneTo1024TapsAndRefusesOutsideThem) {
    for (const std::string& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Fixture f(backend);
        ASSERT_TRUE(f.renderer) << "backend '" << backend << "' is unusable: " << f.why;
        const auto none = std::chrono::milliseconds(0);
        const auto rgba8 = TextureDecl::Format::RGBA8;
        EXPECT_GE(f.renderer->texelRateMs(4, 4, rgba8, 1, 1, none), 0.);
        EXPECT_GE(f.renderer->texelRateMs(4, 4, rgba8, 1024, 1, none), 0.);
        EXPECT_EQ(f.renderer->texelRateMs(4, 4, rgba8, 0, 1, none), -1.);
        EXPECT_EQ(f.renderer->texelRateMs(4, 4, rgba8, 1025, 1, none), -1.);
        EXPECT_EQ(f.renderer->texelRateMs(0, 4, rgba8, 9, 1, none), -1.);
        EXPECT_EQ(f.renderer->texelRateMs(4, 16385, rgba8, 9, 1, none), -1.);
        EXPECT_EQ(f.renderer->texelRateMs(4, 4, rgba8, 9, 0, none), -1.);
    }
}
