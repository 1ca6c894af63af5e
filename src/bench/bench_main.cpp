// glimmer-bench: what running a script through Glimmer costs, against a
// minimal hand-written GL program doing the same two passes on the same
// context, in the same run. Prints figures; asserts nothing.
//
// Phases of `glimmer render`: start-up (context + GL table), compile (images,
// meshes, shaders, targets), render (every needed pass, glFinish), write
// (read back + PNG). Every figure is the median of --repeat runs after one
// warm-up. GPU figures are best read as ratios against the copy pass, a
// full-screen texture copy of the same size timed the same way.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "pipeline/prepare_script.h"
#include "pipeline/watch.h"
#include "pipeline/stats.h"
#include "backends/context.h"
#include "gl/renderer.h"
#include "gl/shader_build.h"
#include "image/image.h"
#include "plan/dependencies.h"
#include "plan/uniform_values.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct Options {
    std::string script;
    std::vector<std::string> backends{"osmesa", "egl-surfaceless"};
    int size = 512;
    int repeat = 5;
    int halfSize = 11;
    double add = 2;
    int pngLevel = kDefaultPngLevel;
    double sliceMs = 25;  // the viewer's slice budget (view/viewer.cpp kSliceMs)
};

std::string readText(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// The hand-written reference: the seed's two programs, two textures, one
// framebuffer per pass, a full-viewport quad each; nothing else.
struct HandWritten {
    const GlApi& gl;
    unsigned image = 0, blur = 0, screen = 0, blurFbo = 0, screenFbo = 0, blurProg = 0, bloomProg = 0, copyProg = 0;
    int size;        // the screen
    int targetSize;  // the blur target, as the script declares it

    unsigned compile(const std::string& vert, const std::string& frag) {
        unsigned p = gl.CreateProgram();
        for (auto [kind, text] : {std::pair{GLenum(GL_VERTEX_SHADER), &vert}, {GLenum(GL_FRAGMENT_SHADER), &frag}}) {
            unsigned s = gl.CreateShader(kind);
            const char* src = text->c_str();
            gl.ShaderSource(s, 1, &src, nullptr);
            gl.CompileShader(s);
            gl.AttachShader(p, s);
            gl.DeleteShader(s);
        }
        gl.LinkProgram(p);
        return p;
    }

    unsigned texture(int w, int h, const void* pixels) {
        unsigned t = 0;
        gl.GenTextures(1, &t);
        gl.BindTexture(GL_TEXTURE_2D, t);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        return t;
    }

    unsigned framebuffer(unsigned tex) {
        unsigned f = 0;
        gl.GenFramebuffers(1, &f);
        gl.BindFramebuffer(GL_FRAMEBUFFER, f);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
        return f;
    }

    void setup(const Image& img, const std::string& shaders) {
        std::string vert = readText(shaders + "/superblur.vert");
        blurProg = compile(vert, readText(shaders + "/superblur.frag"));
        bloomProg = compile(readText(shaders + "/bloom.vert"), readText(shaders + "/bloom.frag"));
        copyProg = compile(vert, "#version 330 compatibility\nuniform sampler2D ImageUnit;\nin vec2 vST;\n"
                                 "void main() { gl_FragColor = texture(ImageUnit, vST); }\n");
        image = texture(img.width, img.height, img.u8.data());
        blur = texture(targetSize, targetSize, nullptr);
        screen = texture(size, size, nullptr);
        blurFbo = framebuffer(blur);
        screenFbo = framebuffer(screen);
    }

    void quad() {
        gl.Begin(GL_QUADS);
        gl.TexCoord2f(0, 0); gl.Vertex2f(-1, -1);
        gl.TexCoord2f(1, 0); gl.Vertex2f(1, -1);
        gl.TexCoord2f(1, 1); gl.Vertex2f(1, 1);
        gl.TexCoord2f(0, 1); gl.Vertex2f(-1, 1);
        gl.End();
    }

    void bind(int unit, unsigned tex) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        gl.BindTexture(GL_TEXTURE_2D, tex);
    }

    void blurPass(int halfSize) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, blurFbo);
        gl.Viewport(0, 0, targetSize, targetSize);
        gl.UseProgram(blurProg);
        bind(5, image);
        gl.Uniform1i(gl.GetUniformLocation(blurProg, "ImageUnit"), 5);
        gl.Uniform1i(gl.GetUniformLocation(blurProg, "uHalfSize"), halfSize);
        quad();
    }

    void bloomPass(double add) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, screenFbo);
        gl.Viewport(0, 0, size, size);
        gl.UseProgram(bloomProg);
        bind(6, blur);
        bind(7, image);
        gl.Uniform1i(gl.GetUniformLocation(bloomProg, "BlurUnit"), 6);
        gl.Uniform1i(gl.GetUniformLocation(bloomProg, "ImageUnit"), 7);
        gl.Uniform1f(gl.GetUniformLocation(bloomProg, "uAdd"), float(add));
        quad();
    }

    void copyPass() {
        gl.BindFramebuffer(GL_FRAMEBUFFER, screenFbo);
        gl.Viewport(0, 0, size, size);
        gl.UseProgram(copyProg);
        bind(5, image);
        gl.Uniform1i(gl.GetUniformLocation(copyProg, "ImageUnit"), 5);
        quad();
    }

    void release() {
        for (unsigned* t : {&image, &blur, &screen}) gl.DeleteTextures(1, t);
        for (unsigned* f : {&blurFbo, &screenFbo}) gl.DeleteFramebuffers(1, f);
        for (unsigned p : {blurProg, bloomProg, copyProg}) gl.DeleteProgram(p);
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl.UseProgram(0);
    }
};

// Times `f` the way the renderer times its passes: on a GPU with a
// GL_TIME_ELAPSED query around it, on a CPU renderer (where the queries mean
// nothing) with glFinish on each side and a wall clock. Median of `repeat`.
template <typename F>
double timed(const GlApi& gl, bool gpu, int repeat, F f) {
    std::vector<double> t;
    f();  // warm-up: first use compiles llvmpipe's code for the shader
    gl.Finish();
    for (int i = 0; i < repeat; ++i) {
        if (gpu) {
            unsigned q = 0;
            gl.GenQueries(1, &q);
            gl.BeginQuery(GL_TIME_ELAPSED, q);
            f();
            gl.EndQuery(GL_TIME_ELAPSED);
            GLuint64 ns = 0;
            gl.GetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
            gl.DeleteQueries(1, &q);
            t.push_back(double(ns) / 1e6);
        } else {
            auto start = Clock::now();
            f();
            gl.Finish();
            t.push_back(msSince(start));
        }
    }
    return median(t);
}

// What a watch costs (issue 28) against the whole frame, wall clock, on the
// same renderer: the watch's draw (the watched pass and the passes feeding
// it, into float targets) and then with the read-back, statistics and
// picture the viewer makes of it each time a slider moves.
struct WatchFigure {
    std::string spec;
    double draw = 0, frame = 0;
    double alone = 0;  // the watched pass alone, its feeding passes kept (the viewer after a uAdd change)
    double readBack = 0;  // frame, then its floats and picture read back whole (what render --watch and a save add)
    double capture = 0, count = 0, colour = 0;  // the parts of `alone`
};
std::vector<WatchFigure> benchWatches(Renderer& r, const Plan& plan, const UniformValues& v, const GlApi& gl, int repeat) {
    std::vector<WatchFigure> out;
    for (const char* text : {"bloom.frag:12:rgbblur", "superblur.frag:27:rgbSum"}) {
        WatchSpec spec;
        std::string why;
        Diagnostics d;
        Watch w;
        if (!parseWatchSpec(text, spec, why) || !startWatch(spec, plan, r, d, w)) continue;
        WatchFigure f{text};
        f.draw = timed(gl, false, repeat, [&] { r.renderWatch(w.pass, v, 0, w.feeding); });
        f.readBack = timed(gl, false, repeat, [&] { drawWatch(r, w, v, 0); r.readWatchCapture(); r.readWatchPicture(); });
        f.frame = timed(gl, false, repeat, [&] { drawWatch(r, w, v, 0); });
        const std::vector<bool> none(plan.passes.size(), false);
        f.alone = timed(gl, false, repeat, [&] { drawWatch(r, w, v, 0, &none); });
        // Its parts, each waited for: the watched pass into its float targets, the
        // GPU's counting (and the read-back of the counts), the colouring.
        f.capture = timed(gl, false, repeat, [&] { r.renderWatch(w.pass, v, 0, none); });
        f.count = timed(gl, false, repeat, [&] { r.sumWatch(0, 1); });
        f.colour = timed(gl, false, repeat, [&] { r.colourWatch(0, 1, 1, {}); });
        out.push_back(f);
    }
    r.dropWatch();
    return out;
}

int benchBackend(const Options& o, const std::string& backendName) {
    BackendChoice choice;
    if (!parseBackend(backendName, choice)) return 2;
    std::vector<double> startup, compile, render, write, loadMs;
    std::map<int, std::vector<double>> passTimes;
    double fullFrame = 0, addChange = 0, addChangeWall = 0, slicedFrame = 0, wholeWall = 0;
    std::map<std::string, std::vector<double>> prepareSteps;
    std::vector<WatchFigure> watches;
    int slicesPerFrame = 0;
    bool gpu = false;  // time with GPU timer queries (a GPU) or glFinish and a wall clock
    std::string rendererName;
    LoadedScript loaded;
    Diagnostics diags;
    ScriptRequest request;
    request.script = o.script;
    request.plan.width = request.plan.height = o.size;
    if (!planScript(request, diags, loaded)) {
        printDiagnostics(diags, loaded.sources, std::cerr);
        return 1;
    }
    UniformValues values(loaded.plan);
    values.applySet(loaded.plan, fmt::format("uHalfSize={}", o.halfSize), diags);
    values.applySet(loaded.plan, fmt::format("uAdd={}", o.add), diags);
    std::string png = (std::filesystem::temp_directory_path() / "glimmer-bench.png").string();

    // Glimmer, whole runs: each repeat makes its own context, as a grader's
    // `glimmer render` of many scripts would.
    for (int i = 0; i <= o.repeat; ++i) {
        auto t0 = Clock::now();
        std::string why;
        auto ctx = createContext(choice, why);
        if (!ctx) {
            std::cerr << backendName << ": " << why << "\n";
            return 1;
        }
        auto r = Renderer::create([&](const char* n) { return ctx->getProcAddress(n); }, why);
        double tStart = msSince(t0);
        GlApi timerGl;  // the bench's own table, for timer queries around the renderer's work: not Glimmer's start-up
        loadGlApi(timerGl, [&](const char* n) { return ctx->getProcAddress(n); }, why);
        auto t1 = Clock::now();
        Diagnostics d;
        LoadedScript run = loaded;  // the files are read each time, as `glimmer render` does
        loadFiles(run, false, d);  // on the CPU: the hand-written program is handed its image decoded
        double tLoad = msSince(t1);
        auto t1b = Clock::now();
        uploadScript(*r, run, false, d);
        r->finish();
        double tCompile = msSince(t1b);
        if (i > 0)
            for (const auto& [step, ms] : r->prepareSteps()) prepareSteps[step].push_back(ms);
        auto t2 = Clock::now();
        r->render(values, 0);
        r->finish();
        double tRender = msSince(t2);
        auto t3 = Clock::now();
        Image img = r->readScreen();
        writePng(png, img, why, o.pngLevel);
        double tWrite = msSince(t3);
        rendererName = r->rendererName();
        gpu = r->gpuTimers();
        if (i == o.repeat) {  // steady state, on the last context
            for (int k = 0; k < o.repeat; ++k) {
                std::vector<PassTiming> timings;
                r->render(values, 0, &timings);
                for (const auto& p : timings) passTimes[p.pass].push_back(p.ms);
            }
            // What `view` does when a slider of the composite moves: only the
            // passes the change reaches run again.
            int bloom = -1;
            for (size_t p = 0; p < loaded.plan.programs.size(); ++p)
                for (const auto& u : loaded.plan.programs[p].uniforms)
                    if (u.name == "uAdd") bloom = int(p);
            if (bloom >= 0) {
                Change change;
                change.programs = {bloom};
                std::vector<bool> only = passesToRun(loaded.plan, change);
                UniformValues v = values;
                fullFrame = timed(timerGl, r->gpuTimers(), o.repeat, [&] { r->render(v, 0); });
                // What `view` does since issue 13: the same whole frame in
                // bands of 25 ms slices (gl/renderer_sliced.cpp), so the cost
                // of slicing is a ratio measured here.
                std::vector<bool> all(loaded.plan.passes.size(), true);
                int slices = 0;
                wholeWall = timed(timerGl, false, o.repeat, [&] { r->render(v, 0); });
                slicedFrame = timed(timerGl, false, o.repeat, [&] {
                    SlicedFrame f = r->startFrame(v, 0, all);
                    slices = 1;
                    while (!r->renderSlice(f, o.sliceMs)) ++slices;
                });
                slicesPerFrame = slices;
                watches = benchWatches(*r, loaded.plan, v, timerGl, o.repeat);
                int k = 0;
                addChange = timed(timerGl, r->gpuTimers(), o.repeat, [&] {
                    v.set(bloom, "uAdd", {(k++ % 2) ? 1.0 : 3.0});
                    r->render(v, 0, nullptr, &only);
                });
                addChangeWall = timed(timerGl, false, o.repeat, [&] {  // as the watch's, which waits for its counts
                    v.set(bloom, "uAdd", {(k++ % 2) ? 1.0 : 3.0});
                    r->render(v, 0, nullptr, &only);
                });
            }
        }
        if (i == 0) continue;  // the first run warms caches and the driver
        startup.push_back(tStart);
        compile.push_back(tCompile);
        loadMs.push_back(tLoad);
        render.push_back(tRender);
        write.push_back(tWrite);
    }

    // The hand-written program, whole runs on fresh contexts too, so its
    // first frame is compared with Glimmer's first frame.
    Image img;
    const TextureDecl* input = nullptr;
    int targetSize = o.size;
    for (const auto& t : loaded.plan.textures) {
        if (t.source == TextureDecl::Source::File) input = &t;
        else targetSize = t.width;
    }
    std::string why;
    if (!input || !loadImage(input->path, img, why)) {
        std::cerr << "bench: the script has no image to blur\n";
        return 1;
    }
    std::string shaderDir = std::filesystem::path(o.script).parent_path().string() + "/../shaders";
    std::vector<double> hwStartup, hwCompile, hwFirst;
    double hwBlur = 0, hwBloom = 0, copy = 0;
    for (int i = 0; i <= o.repeat; ++i) {
        auto t0 = Clock::now();
        auto ctx = createContext(choice, why);
        GlApi gl;
        loadGlApi(gl, [&](const char* n) { return ctx->getProcAddress(n); }, why);
        double tStart = msSince(t0);
        HandWritten hw{gl, 0, 0, 0, 0, 0, 0, 0, 0, o.size, targetSize};
        auto t1 = Clock::now();
        hw.setup(img, shaderDir);
        gl.Finish();
        double tCompile = msSince(t1);
        auto t2 = Clock::now();
        hw.blurPass(o.halfSize);
        hw.bloomPass(o.add);
        gl.Finish();
        double tFirst = msSince(t2);
        if (i == o.repeat) {  // steady state, on the last context
            hwBlur = timed(gl, gpu, o.repeat, [&] { hw.blurPass(o.halfSize); });
            hwBloom = timed(gl, gpu, o.repeat, [&] { hw.bloomPass(o.add); });
            copy = timed(gl, gpu, o.repeat, [&] { hw.copyPass(); });
        }
        hw.release();
        if (i == 0) continue;
        hwStartup.push_back(tStart);
        hwCompile.push_back(tCompile);
        hwFirst.push_back(tFirst);
    }

    double mRender = median(render);
    fmt::print("\n== {} on {}: {} at {}x{}, uHalfSize {}, uAdd {}, median of {} ==\n", backendName, rendererName,
               o.script, o.size, o.size, o.halfSize, o.add, o.repeat);
    fmt::print("{:<28}{:>12}{:>14}{:>10}\n", "phase", "glimmer ms", "hand-written", "ratio");
    auto row = [](const char* name, double g, double h) {
        fmt::print("{:<28}{:>12.2f}{:>14.2f}{:>10.2f}\n", name, g, h, h > 0 ? g / h : 0.0);
    };
    row("start-up (context, GL)", median(startup), median(hwStartup));
    fmt::print("{:<28}{:>12.2f}   (CPU: read and decode files; not in either figure below)\n", "load files",
               median(loadMs));
    row("compile (upload, link)", median(compile), median(hwCompile));
    for (const char* step : {"textures", "meshes", "programs", "checks", "targets"})
        if (prepareSteps.count(step))
            fmt::print("  {:<26}{:>12.2f}   (wall clock, no glFinish)\n", step, median(prepareSteps[step]));
    row("first frame (both passes)", mRender, median(hwFirst));
    std::error_code sizeError;
    fmt::print("{:<28}{:>12.2f}   PNG level {}, {} bytes\n", "write (read back, PNG)", median(write), o.pngLevel,
               std::filesystem::file_size(png, sizeError));
    fmt::print("steady state, one context, after a warm-up:\n");
    for (const auto& [pass, t] : passTimes) {
        const Pass& p = loaded.plan.passes[size_t(pass)];
        double hwPass = p.targets.empty() ? hwBloom : hwBlur;
        row(fmt::format("  pass {} (line {}, {})", pass, p.loc.line, p.targets.empty() ? "screen" : "target").c_str(),
            median(t), hwPass);
    }
    if (addChange > 0)
        fmt::print("{:<28}{:>12.2f}   full frame {:.2f} ms: {:.0f}x faster (only the passes a uAdd change reaches)\n",
                   "uAdd change, new picture", addChange, fullFrame, fullFrame / addChange);
    if (slicedFrame > 0)
        fmt::print("{:<28}{:>12.2f}   whole frame {:.2f} ms (wall clock): {:.2f}x, in {} slices of {:g} ms (what view draws)\n",
                   "sliced frame", slicedFrame, wholeWall, slicedFrame / wholeWall, slicesPerFrame, o.sliceMs);
    for (const auto& w : watches)
        fmt::print("{:<28}{:>12.2f}   whole frame {:.2f} ms (wall clock): {:.2f}x; the draw alone {:.2f} ms ({:.2f}x), "
                   "the rest counting and colouring on the GPU; with the floats and picture read back {:.2f} ms\n",
                   "watch " + w.spec.substr(0, w.spec.find(':')), w.frame, wholeWall, w.frame / wholeWall, w.draw,
                   w.draw / wholeWall, w.readBack);
    for (const auto& w : watches)
        if (w.spec.rfind("bloom", 0) == 0)
            fmt::print("{:<28}{:>12.2f}   the watched pass alone, the blur kept (what view draws when uAdd moves): "
                       "{:.2f}x the uAdd change without a watch ({:.2f} ms, wall clock); of it the pass into its "
                       "float targets {:.2f} ms ({:.2f}x), counting {:.2f} ms, colouring {:.2f} ms\n",
                       "watch bloom.frag, uAdd", w.alone, addChangeWall > 0 ? w.alone / addChangeWall : 0., addChangeWall,
                       w.capture, addChangeWall > 0 ? w.capture / addChangeWall : 0., w.count, w.colour);
    fmt::print("{:<28}{:>12.2f}   (full-screen texture copy, {}x{})\n", "copy pass", copy, o.size, o.size);
    fmt::print("{:<28}{:>12.1f}   blur pass / copy pass\n", "blur in copies", hwBlur / copy);
    fmt::print("{:<28}{:>12.1f}   bloom pass / copy pass\n", "bloom in copies", hwBloom / copy);
    return 0;
}

}  // namespace
}  // namespace glimmer

namespace glimmer {
int formatFigures(const std::string& backendName);
}

int main(int argc, char** argv) {
    glimmer::Options o;
    CLI::App app{"glimmer-bench: Glimmer against a hand-written GL program, same passes, same run"};
    app.add_option("script", o.script, "the bloom script (default scripts/bloom.glib)");
    app.add_option("--backend", o.backends, "backends to measure (default osmesa egl-surfaceless)");
    app.add_option("--size", o.size, "square output size (default 512)");
    app.add_option("--repeat", o.repeat, "runs per figure, after one warm-up (default 5)");
    app.add_option("--half-size", o.halfSize, "uHalfSize (default 11)");
    app.add_option("--add", o.add, "uAdd (default 2)");
    app.add_option("--slice-ms", o.sliceMs, "the slice budget of the sliced-frame figure (default 25, as view)");
    app.add_option("--png-level", o.pngLevel, "zlib level of the PNG written, 0 to 9 (default 3)")
        ->check(CLI::Range(0, 9));
    CLI11_PARSE(app, argc, argv);
    if (o.script.empty()) o.script = std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib";
    int rc = 0;
    for (const auto& b : o.backends) rc = std::max(rc, glimmer::benchBackend(o, b));
    rc = std::max(rc, glimmer::formatFigures(o.backends.front()));
    return rc;
}
