// A backend makes an OpenGL context current and says how to find GL entry
// points. It draws nothing: the renderer does, the same way on every backend.
#pragma once
#include <memory>
#include <string>


namespace glimmer {

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void* getProcAddress(const char* name) = 0;
    virtual std::string name() const = 0;  // "osmesa", "egl-device", "egl-surfaceless", "egl-gles", "glfw"
};

enum class BackendChoice { Auto, OsMesa, Egl, EglDevice, EglSurfaceless, EglGles };

// Parses "auto", "osmesa", "egl", "egl-device", "egl-surfaceless", "egl-gles".
bool parseBackend(const std::string& text, BackendChoice& out);

std::unique_ptr<GlContext> createOsMesaContext(std::string& error);
// A GPU through EGL_EXT_platform_device; software devices are skipped.
std::unique_ptr<GlContext> createEglDeviceContext(std::string& error);
// Mesa's surfaceless platform (llvmpipe on a machine without a GPU).
std::unique_ptr<GlContext> createEglSurfacelessContext(std::string& error);
// OpenGL ES 3.0 on Mesa's surfaceless platform: WebGL 2's feature level on
// the desktop, so the browser's drawing path is tested natively. Shaders
// must be GLSL ES (the translated ones); chosen only by name, never by auto.
std::unique_ptr<GlContext> createEglGlesContext(std::string& error);

// The browser build's only backend (backends/webgl_context.cpp): WebGL 2 on
// the page's canvas named by the CSS selector ("#canvas").
// `floatTargets` false leaves EXT_color_buffer_float off, as a browser
// without it would (the test of what such a browser says).
std::unique_ptr<GlContext> createWebGl2Context(const char* canvasSelector, std::string& error, bool floatTargets = true);

// auto: a GPU through EGL, else OSMesa, else EGL surfaceless. egl: device,
// else surfaceless. `error` collects why each refused.
std::unique_ptr<GlContext> createContext(BackendChoice choice, std::string& error);

}  // namespace glimmer
