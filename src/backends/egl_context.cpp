#include <cstring>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "backends/context.h"
#include "backends/driver_shader_cache.h"

namespace glimmer {
namespace {

class EglContext : public GlContext {
public:
    EglContext(EGLDisplay dpy, EGLContext ctx, std::string name) : dpy_(dpy), ctx_(ctx), name_(std::move(name)) {}
    ~EglContext() override {
        eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(dpy_, ctx_);
        eglTerminate(dpy_);
    }
    void* getProcAddress(const char* name) override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
    std::string name() const override { return name_; }

private:
    EGLDisplay dpy_;
    EGLContext ctx_;
    std::string name_;
};

bool hasExtension(const char* list, const char* ext) {
    if (!list) return false;
    size_t n = std::strlen(ext);
    for (const char* p = list; (p = std::strstr(p, ext)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

enum class Api { DesktopCompat, Es30 };

// A GPU is shared by every process that draws on it: when one of them hangs
// the GPU or is killed mid-draw, the driver may reset the engine, and the
// others' work is lost without an error unless their contexts asked to be
// told (glGetGraphicsResetStatus; batch's workers ask after every picture
// and draw the script again elsewhere). EGL 1.5's own attribute; a driver
// that refuses it gets the plain context.
enum class Resets { Ignore, Report };

// Makes a surfaceless context on an initialised display: desktop GL 3.3
// compatibility, or OpenGL ES 3.0, the feature level of WebGL 2.
std::unique_ptr<GlContext> makeContext(EGLDisplay dpy, const std::string& name, std::string& error,
                                       Api api = Api::DesktopCompat, Resets resets = Resets::Ignore) {
    const bool es = api == Api::Es30;
    if (!hasExtension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        error = name + ": no EGL_KHR_surfaceless_context";
        eglTerminate(dpy);
        return nullptr;
    }
    // Nothing is drawn to an EGL surface, so no config is needed where the
    // display allows that (Mesa's surfaceless platform offers none for GL).
    EGLConfig config = EGL_NO_CONFIG_KHR;
    EGLint count = 0;
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
    if (!hasExtension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_no_config_context") &&
        (!eglChooseConfig(dpy, configAttribs, &config, 1, &count) || count < 1)) {
        error = name + (es ? ": no EGL config for OpenGL ES 3" : ": no EGL config for desktop OpenGL");
        eglTerminate(dpy);
        return nullptr;
    }
    if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        error = name + (es ? ": cannot bind the OpenGL ES API" : ": cannot bind the desktop OpenGL API");
        eglTerminate(dpy);
        return nullptr;
    }
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    const EGLint esAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    const EGLint reportingAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                       EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY, EGL_LOSE_CONTEXT_ON_RESET,
                                       EGL_NONE};
    EGLContext ctx = EGL_NO_CONTEXT;
    if (!es && resets == Resets::Report) ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, reportingAttribs);
    if (ctx == EGL_NO_CONTEXT) ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, es ? esAttribs : contextAttribs);
    if (ctx == EGL_NO_CONTEXT) {
        error = name + (es ? ": cannot create an OpenGL ES 3.0 context" : ": cannot create a GL 3.3 compatibility context");
        eglTerminate(dpy);
        return nullptr;
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        error = name + ": cannot make the context current";
        eglDestroyContext(dpy, ctx);
        eglTerminate(dpy);
        return nullptr;
    }
    return std::make_unique<EglContext>(dpy, ctx, name);
}

template <typename F>
F eglProc(const char* name) {
    return reinterpret_cast<F>(eglGetProcAddress(name));
}

}  // namespace

std::unique_ptr<GlContext> createEglDeviceContext(std::string& error) {
    disableMesaShaderCache();  // before the driver loads: logs must not depend on an earlier run
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExts, "EGL_EXT_platform_device")) {
        error = "egl-device: no EGL_EXT_platform_device";
        return nullptr;
    }
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (!queryDevices || !queryDeviceString || !getPlatformDisplay) {
        error = "egl-device: device functions missing";
        return nullptr;
    }
    EGLint n = 0;
    std::vector<EGLDeviceEXT> devices(16);
    if (!queryDevices(EGLint(devices.size()), devices.data(), &n) || n == 0) {
        error = "egl-device: no EGL devices";
        return nullptr;
    }
    for (EGLint i = 0; i < n; ++i) {
        // Mesa lists llvmpipe as a device too; that is the CPU, not a GPU.
        if (hasExtension(queryDeviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software")) continue;
        EGLDisplay dpy = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr)) continue;
        if (auto c = makeContext(dpy, "egl-device", error, Api::DesktopCompat, Resets::Report)) return c;
    }
    if (error.empty()) error = "egl-device: no GPU among the EGL devices";
    return nullptr;
}

namespace {

EGLDisplay surfacelessDisplay() {
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    EGLDisplay dpy = getPlatformDisplay ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                                        : EGL_NO_DISPLAY;
    if (dpy != EGL_NO_DISPLAY && !eglInitialize(dpy, nullptr, nullptr)) return EGL_NO_DISPLAY;
    return dpy;
}

}  // namespace

std::unique_ptr<GlContext> createEglGlesContext(std::string& error) {
    disableMesaShaderCache();  // before the driver loads: logs must not depend on an earlier run
    EGLDisplay dpy = surfacelessDisplay();
    if (dpy == EGL_NO_DISPLAY) {
        error = "egl-gles: no Mesa surfaceless display";
        return nullptr;
    }
    return makeContext(dpy, "egl-gles", error, Api::Es30);
}

std::unique_ptr<GlContext> createEglSurfacelessContext(std::string& error) {
    disableMesaShaderCache();  // before the driver loads: logs must not depend on an earlier run
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
        error = "egl-surfaceless: no EGL_MESA_platform_surfaceless";
        return nullptr;
    }
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    EGLDisplay dpy = getPlatformDisplay ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                                        : EGL_NO_DISPLAY;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr)) {
        error = "egl-surfaceless: cannot initialise the display";
        return nullptr;
    }
    return makeContext(dpy, "egl-surfaceless", error);
}

}  // namespace glimmer
