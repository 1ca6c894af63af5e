// Runs a script through the real pipeline (parse, plan, backend, renderer)
// and hands back pixels, for tests that compare them with a CPU reference.
#pragma once
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/prepare_script.h"
#include "backends/context.h"
#include "gl/renderer.h"
#include "image/image.h"
#include "plan/uniform_values.h"

namespace glimmer::testing {

struct Rendered {
    bool ok = false;
    std::string error;  // why not ok: the diagnostics, printed
    Image screen;
    std::map<int, Image> units;  // texture unit -> its texture when the script ended
    std::map<int, Image> floats; // the same read back as float RGBA
    std::string warnings;        // every diagnostic, printed
};

// The backends the render tests run on: GLIMMER_TEST_BACKENDS (comma list),
// else both CPU backends. A GPU machine sets it to "egl-device".
// The list is read when a test runs, never when tests are listed, so the
// same cases exist whatever it says. A name Glimmer does not know, or a list
// naming nothing, fails the calling test (naming it); a known backend that
// cannot make a context fails in renderScript, naming it too. Never a skip.
inline std::vector<std::string> testBackends() {
    const char* env = std::getenv("GLIMMER_TEST_BACKENDS");
    std::string list = env && *env ? env : "osmesa,egl-surfaceless";
    std::vector<std::string> out;
    std::stringstream ss(list);
    for (std::string b; std::getline(ss, b, ',');) {
        if (b.empty()) continue;
        BackendChoice choice;
        if (!parseBackend(b, choice))
            ADD_FAILURE() << "GLIMMER_TEST_BACKENDS names an unknown backend '" << b << "'";
        out.push_back(b);
    }
    if (out.empty()) {
        ADD_FAILURE() << "GLIMMER_TEST_BACKENDS='" << list << "' names no backend";
        out.push_back("(none)");  // renderScript then fails naming it
    }
    return out;
}

// A context of `backend` with a renderer holding `loaded`, uploaded, or
// `error` naming the step that failed. For a test that draws more than
// once, or between reads; renderScript draws once with it.
struct Rig {
    std::unique_ptr<GlContext> context;
    std::unique_ptr<Renderer> renderer;  // destroyed before its context
    std::string error;
};

// A test's hand on the GL table: called with each function's name and the
// driver's function (null if the driver has none), it returns what the
// renderer calls instead: the driver's, or a counter or stand-in of the test's.
using ProcWrap = std::function<void*(std::string_view name, void* driver)>;

// A context of `backend` and a renderer on it whose GL table goes through
// `wrap` (none: the driver's functions), nothing loaded yet: a test that
// expects loading to fail loads itself. `error` names the step that failed.
inline Rig makeWrappedRig(const std::string& backend, const ProcWrap& wrap = {}) {
    Rig rig;
    BackendChoice choice;
    if (!parseBackend(backend, choice)) {
        rig.error = "unknown backend '" + backend + "'";
        return rig;
    }
    std::string why;
    rig.context = createContext(choice, why);
    GlContext* context = rig.context.get();
    if (context)
        rig.renderer = Renderer::create(
            [context, &wrap](const char* name) {
                void* driver = context->getProcAddress(name);
                return wrap ? wrap(name, driver) : driver;
            },
            why);
    if (!rig.renderer) rig.error = "backend '" + backend + "' is unusable: " + why;
    return rig;
}

inline Rig makeRig(const std::string& backend, LoadedScript& loaded, Diagnostics& diags,
                   const ProcWrap& wrap = {}) {
    Rig rig = makeWrappedRig(backend, wrap);
    if (rig.renderer && !loadAndUpload(*rig.renderer, loaded, false, diags)) {
        rig.error = "prepare failed";
        rig.renderer.reset();
    }
    return rig;
}

inline Rendered renderScript(const std::string& backendName, const std::string& script,
                             const std::vector<std::string>& sets, const std::vector<int>& readUnits,
                             PlanOptions options = {}) {
    Rendered r;
    Diagnostics diags;
    LoadedScript loaded;
    for (int u : readUnits) options.keepTargets.insert(u);
    options.includeDirs.push_back(std::string(GLIMMER_SOURCE_DIR) + "/shaders");
    auto fail = [&](const std::string& why) {
        std::ostringstream out;
        printDiagnostics(diags, loaded.sources, out);
        r.error = why + "\n" + out.str();
        return r;
    };
    if (!loadScript(script, options, diags, loaded) || diags.hasErrors()) return fail("script did not load");
    UniformValues values(loaded.plan);
    for (const auto& s : sets)
        if (!values.applySet(loaded.plan, s, diags)) return fail("--set " + s);

    Rig rig = makeRig(backendName, loaded, diags);
    if (!rig.renderer) return fail(rig.error);
    Renderer* renderer = rig.renderer.get();
    renderer->render(values, 0.0);
    r.screen = renderer->readScreen();
    for (int u : readUnits) {
        auto it = loaded.plan.finalUnits.find(u);
        if (it != loaded.plan.finalUnits.end()) {
            r.units[u] = renderer->readTexture(it->second);
            r.floats[u] = renderer->readTextureFloat(it->second);
        }
    }
    std::ostringstream printed;
    printDiagnostics(diags, loaded.sources, printed);
    r.warnings = printed.str();
    r.ok = true;
    return r;
}

// Largest per-channel difference (RGB) in 8-bit steps, and where.
struct Difference {
    int maxSteps = 0;
    int x = -1, y = -1;
    long pixelsOver1 = 0;
};

inline Difference compareRgb(const Image& a, const Image& b) {
    Difference d;
    if (a.width != b.width || a.height != b.height) {
        d.maxSteps = 256;
        return d;
    }
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            size_t i = (size_t(y) * size_t(a.width) + size_t(x)) * 4;
            int worst = 0;
            for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.u8[i + c]) - int(b.u8[i + c])));
            if (worst > 1) ++d.pixelsOver1;
            if (worst > d.maxSteps) {
                d.maxSteps = worst;
                d.x = x;
                d.y = y;
            }
        }
    }
    return d;
}

}  // namespace glimmer::testing
