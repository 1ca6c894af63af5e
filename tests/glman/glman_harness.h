// Helpers for the glman parity tests: the data folder, a pipeline run that
// keeps the diagnostics and the renderer (for `check`-style runs and noise
// checks), reading stored reference pictures and pixels.
#pragma once
#include <filesystem>
#include <memory>
#include <string>

#include "pipeline/prepare_script.h"
#include "backends/context.h"
#include "gl/renderer.h"
#include "image/image.h"
#include "plan/uniform_values.h"
#include "render/render_harness.h"

namespace glimmer::glmantest {

inline std::string dataDir() { return std::string(GLIMMER_TEST_DATA) + "/glman"; }
inline std::string script(const std::string& name) { return dataDir() + "/" + name + ".glib"; }

// A script taken through load, plan, prepare (and render) on OSMesa, keeping
// everything for the test to look at.
struct Run {
    Diagnostics diags;
    LoadedScript loaded;
    std::unique_ptr<GlContext> context;
    std::unique_ptr<Renderer> renderer;
    bool prepared = false;
    std::string setupError;  // no context or renderer
    Image screen;

    std::string printed() const {
        std::ostringstream out;
        printDiagnostics(diags, loaded.sources, out);
        return setupError + out.str();
    }
    std::vector<std::string> messages(Severity s) const {
        std::vector<std::string> out;
        for (const auto& d : diags.all())
            if (d.severity == s) out.push_back(d.message);
        return out;
    }
};

// `everything`: make every program and texture, as `glimmer check` does.
inline std::unique_ptr<Run> runPipeline(const std::string& path, bool everything, bool draw) {
    auto r = std::make_unique<Run>();
    PlanOptions options;
    if (!loadScript(path, options, r->diags, r->loaded)) return r;
    BackendChoice choice;
    parseBackend("osmesa", choice);
    std::string why;
    r->context = createContext(choice, why);
    if (!r->context) {
        r->setupError = why;
        return r;
    }
    GlContext* ctx = r->context.get();
    r->renderer = Renderer::create([ctx](const char* n) { return ctx->getProcAddress(n); }, why);
    if (!r->renderer) {
        r->setupError = why;
        return r;
    }
    if (r->diags.hasErrors()) return r;
    r->prepared = loadAndUpload(*r->renderer, r->loaded, everything, r->diags);
    if (r->prepared && draw) {
        UniformValues values(r->loaded.plan);
        r->renderer->render(values, 0.0);
        r->screen = r->renderer->readScreen();
    }
    return r;
}

inline const std::uint8_t* pixel(const Image& img, int x, int y) {
    return &img.u8[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
}

}  // namespace glimmer::glmantest
