#include <dlfcn.h>

#include <vector>

#include "backends/context.h"
#include "backends/driver_shader_cache.h"
// osmesa.h needs GLAPI, which other GL headers may have consumed.
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>

namespace glimmer {
namespace {

// OSMesa is opened at run time, not linked: Mesa removed it in 25.1, and a
// GPU machine may have none, yet the same glimmer binary must run there
// through EGL.
struct OsMesaLibrary {
    decltype(&::OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&::OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&::OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&::OSMesaGetProcAddress) getProcAddress = nullptr;

    static const OsMesaLibrary* open(std::string& error) {
        static OsMesaLibrary lib;
        static bool tried = false;
        static std::string why;
        if (!tried) {
            tried = true;
            void* h = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
            if (!h) h = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
            if (!h) {
                why = "osmesa: libOSMesa is not installed (Debian: libosmesa6)";
            } else {
                lib.createContextAttribs = reinterpret_cast<decltype(lib.createContextAttribs)>(dlsym(h, "OSMesaCreateContextAttribs"));
                lib.makeCurrent = reinterpret_cast<decltype(lib.makeCurrent)>(dlsym(h, "OSMesaMakeCurrent"));
                lib.destroyContext = reinterpret_cast<decltype(lib.destroyContext)>(dlsym(h, "OSMesaDestroyContext"));
                lib.getProcAddress = reinterpret_cast<decltype(lib.getProcAddress)>(dlsym(h, "OSMesaGetProcAddress"));
                if (!lib.createContextAttribs || !lib.makeCurrent || !lib.destroyContext || !lib.getProcAddress)
                    why = "osmesa: libOSMesa lacks OSMesaCreateContextAttribs";
            }
        }
        error = why;
        return why.empty() ? &lib : nullptr;
    }
};

class OsMesaContext : public GlContext {
public:
    OsMesaContext(const OsMesaLibrary& lib, OSMesaContext ctx) : lib_(lib), ctx_(ctx), pixels_(4) {}
    ~OsMesaContext() override { lib_.destroyContext(ctx_); }

    bool makeCurrent() {
        // The renderer draws into framebuffer objects; OSMesa still wants a
        // buffer of its own to make the context current.
        return lib_.makeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, 1, 1);
    }
    void* getProcAddress(const char* name) override {
        return reinterpret_cast<void*>(lib_.getProcAddress(name));
    }
    std::string name() const override { return "osmesa"; }

private:
    const OsMesaLibrary& lib_;
    OSMesaContext ctx_;
    std::vector<unsigned char> pixels_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext(std::string& error) {
    disableMesaShaderCache();  // before the driver loads: logs must not depend on an earlier run
    const OsMesaLibrary* lib = OsMesaLibrary::open(error);
    if (!lib) return nullptr;
    // glman's scripts need the compatibility profile: gl_ModelViewProjectionMatrix,
    // gl_Vertex, gl_MultiTexCoord0.
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = lib->createContextAttribs(attribs, nullptr);
    if (!ctx) {
        error = "OSMesa could not create a GL 3.3 compatibility context";
        return nullptr;
    }
    auto c = std::make_unique<OsMesaContext>(*lib, ctx);
    if (!c->makeCurrent()) {
        error = "OSMesa could not make its context current";
        return nullptr;
    }
    return c;
}

}  // namespace glimmer
