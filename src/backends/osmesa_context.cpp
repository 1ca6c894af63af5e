#include <vector>

#include "backends/context.h"
// osmesa.h needs GLAPI, which other GL headers may have consumed.
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>

namespace glimmer {
namespace {

class OsMesaContext : public GlContext {
public:
    OsMesaContext(OSMesaContext ctx) : ctx_(ctx), pixels_(4) {}
    ~OsMesaContext() override { OSMesaDestroyContext(ctx_); }

    bool makeCurrent() {
        // The renderer draws into framebuffer objects; OSMesa still wants a
        // buffer of its own to make the context current.
        return OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, 1, 1);
    }
    void* getProcAddress(const char* name) override {
        return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
    }
    std::string name() const override { return "osmesa"; }

private:
    OSMesaContext ctx_;
    std::vector<unsigned char> pixels_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext(std::string& error) {
    // glman's scripts need the compatibility profile: gl_ModelViewProjectionMatrix,
    // gl_Vertex, gl_MultiTexCoord0.
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) {
        error = "OSMesa could not create a GL 3.3 compatibility context";
        return nullptr;
    }
    auto c = std::make_unique<OsMesaContext>(ctx);
    if (!c->makeCurrent()) {
        error = "OSMesa could not make its context current";
        return nullptr;
    }
    return c;
}

}  // namespace glimmer
