// The browser build's drawing entry point: `glimmer render` of a script on
// the page's WebGL 2 canvas, through the same steps as the desktop
// (pipeline/prepare_script.h: plan, load files, upload; the one Renderer).
// WebGL 2 takes GLSL ES 3.00 only: until the page translates classroom
// shaders, a script draws here when its shaders are GLSL ES (the built-ins
// by the names in shader/compat_builtins.h).
//
// Contract, for the page (src/web/page/glimmer-page.js):
//   glimmer_render(path, width, height, sets) -> 0 drawn, 1 script errors,
//       2 usage errors (an unreadable script, a bad --set); `sets` is
//       "NAME=VALUE" entries separated by ';'. The picture is presented on
//       #canvas and kept for glimmer_pixels.
//   glimmer_pixels() -> RGBA bytes of the last picture, top row first
//   glimmer_pixels_width(), glimmer_pixels_height()
//   glimmer_time_frames(n) -> the mean wall time in ms of n more frames of
//       the last drawn script, each finished before the clock stops (a
//       one-pixel read: WebGL's finish returns before the GPU process has
//       drawn); -1 when none is drawn. The page's figure against the desktop's (PERFORMANCE.md).
//   glimmer_last_output() (page_check.cpp) -> the diagnostics, as the desktop
//       prints them
#include <emscripten/emscripten.h>

#include <chrono>
#include <memory>
#include <sstream>
#include <string>

#include "backends/context.h"
#include "pipeline/console.h"
#include "pipeline/prepare_script.h"
#include "image/image.h"
#include "plan/uniform_values.h"
#include "web/page_state.h"

namespace {

std::unique_ptr<glimmer::GlContext> context;  // one for the page's life
glimmer::Image lastPicture;
// The last drawn scene, kept for glimmer_time_frames (the renderer owns GL
// objects of the one context, so it goes before a new one is made).
std::unique_ptr<glimmer::Renderer> lastRenderer;
std::unique_ptr<glimmer::UniformValues> lastValues;

}  // namespace

namespace glimmer_web {

// ?no-float-targets: the page's context without EXT_color_buffer_float, as
// a browser lacking it (set before the first context is made).
bool floatTargets = true;

glimmer::GlContext* pageContext(std::string* why) {
    std::string reason;
    if (!context) context = glimmer::createWebGl2Context("#canvas", reason, floatTargets);
    if (!context && why) *why = reason;
    return context.get();
}

glimmer::Image& pagePicture() { return lastPicture; }

std::vector<std::string> splitSets(const std::string& text) {
    std::vector<std::string> out;
    std::string item;
    std::istringstream in(text);
    while (std::getline(in, item, ';'))
        if (!item.empty()) out.push_back(item);
    return out;
}

}  // namespace glimmer_web

extern "C" {

// The page's ?no-float-targets (tools/test-web.sh): a context without
// EXT_color_buffer_float, as some phones' browsers have. Before anything is drawn.
EMSCRIPTEN_KEEPALIVE void glimmer_without_float_targets() { glimmer_web::floatTargets = false; }

EMSCRIPTEN_KEEPALIVE int glimmer_render(const char* path, int width, int height, const char* sets) {
    using namespace glimmer;
    setVerbosity(Verbosity::Normal);
    Diagnostics diags;
    LoadedScript loaded;
    std::ostringstream out;
    auto finish = [&](int code) {
        printDiagnostics(diags, loaded.sources, out);
        glimmer_web::setLastOutput(out.str());
        return code;
    };
    PlanOptions options;
    options.width = width;
    options.height = height;
    // The exit codes of the desktop's openSession: 2 unreadable, 1 errors.
    if (!loadScript(path ? path : "", options, diags, loaded)) return finish(2);
    if (diags.hasErrors()) return finish(1);
    UniformValues values(loaded.plan);
    for (const std::string& s : glimmer_web::splitSets(sets ? sets : ""))
        if (!values.applySet(loaded.plan, s, diags)) return finish(2);
    std::string why;
    if (!glimmer_web::pageContext(&why)) {
        out << "glimmer: error: " << why << "\n";
        return finish(1);
    }
    lastRenderer.reset();
    lastValues.reset();
    auto renderer = Renderer::create([](const char* n) { return context->getProcAddress(n); }, why);
    if (!renderer) {
        out << "glimmer: error: " << why << "\n";
        return finish(1);
    }
    if (!loadAndUpload(*renderer, loaded, false, diags)) return finish(1);
    renderer->render(values, 0.0);
    lastPicture = renderer->readScreen();
    renderer->present(-1, lastPicture.width, lastPicture.height);
    lastRenderer = std::move(renderer);
    lastValues = std::make_unique<UniformValues>(std::move(values));
    return finish(0);
}

EMSCRIPTEN_KEEPALIVE const unsigned char* glimmer_pixels() { return lastPicture.u8.data(); }
EMSCRIPTEN_KEEPALIVE int glimmer_pixels_width() { return lastPicture.width; }
EMSCRIPTEN_KEEPALIVE int glimmer_pixels_height() { return lastPicture.height; }

EMSCRIPTEN_KEEPALIVE double glimmer_time_frames(int n) {
    if (!lastRenderer || n <= 0) return -1;
    lastRenderer->finish();
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) {
        lastRenderer->render(*lastValues, 0.0);
        lastRenderer->finish();
    }
    std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    return took.count() / n;
}

}  // extern "C"
