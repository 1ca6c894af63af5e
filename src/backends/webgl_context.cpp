// The browser's backend: a WebGL 2 context on a canvas of the page. Like
// the others it only makes the context current and hands over
// getProcAddress; WebGL 2 is OpenGL ES 3.0, so the renderer takes its ES
// path (gl/gl_api.h: GlApi::es). Built only by the browser build (src/web).
#include <emscripten/html5.h>
#include <emscripten/html5_webgl.h>

#include <string>

#include "backends/context.h"

namespace glimmer {
namespace {

class WebGlContext : public GlContext {
public:
    explicit WebGlContext(EMSCRIPTEN_WEBGL_CONTEXT_HANDLE ctx) : ctx_(ctx) {}
    ~WebGlContext() override { emscripten_webgl_destroy_context(ctx_); }
    void* getProcAddress(const char* name) override { return emscripten_webgl_get_proc_address(name); }  // WebGL 1 and 2 names
    std::string name() const override { return "webgl2"; }

private:
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE ctx_;
};

}  // namespace

std::unique_ptr<GlContext> createWebGl2Context(const char* canvasSelector, std::string& error, bool floatTargets) {
    EmscriptenWebGLContextAttributes attrs;
    emscripten_webgl_init_context_attributes(&attrs);
    attrs.majorVersion = 2;
    attrs.minorVersion = 0;
    attrs.alpha = false;
    attrs.depth = true;
    attrs.antialias = false;               // the picture is drawn into targets, as on the desktop
    attrs.preserveDrawingBuffer = true;    // the page reads the canvas back (a saved PNG, the tests)
    // Emscripten turns on every extension it knows by default, the float
    // render targets' (EXT_color_buffer_float, _half_float) among them;
    // without them, only what is turned on below.
    attrs.enableExtensionsByDefault = floatTargets;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE ctx = emscripten_webgl_create_context(canvasSelector, &attrs);
    if (ctx <= 0) {
        error = "webgl2: this browser cannot make a WebGL 2 context";
        return nullptr;
    }
    emscripten_webgl_make_context_current(ctx);
    // Float render targets (RGBA16F, RGBA32F: the bloom lab's HDR passes).
    // Left off only to show what a browser without it says (test-web).
    if (floatTargets) emscripten_webgl_enable_extension(ctx, "EXT_color_buffer_float");
    emscripten_webgl_enable_extension(ctx, "OES_texture_float_linear");
    return std::make_unique<WebGlContext>(ctx);
}

}  // namespace glimmer
