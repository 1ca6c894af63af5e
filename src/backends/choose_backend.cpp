#include "backends/context.h"

#include <vector>

namespace glimmer {

bool parseBackend(const std::string& text, BackendChoice& out) {
    if (text == "auto") out = BackendChoice::Auto;
    else if (text == "osmesa") out = BackendChoice::OsMesa;
    else if (text == "egl") out = BackendChoice::Egl;
    else if (text == "egl-device") out = BackendChoice::EglDevice;
    else if (text == "egl-surfaceless") out = BackendChoice::EglSurfaceless;
    else if (text == "egl-gles") out = BackendChoice::EglGles;
    else return false;
    return true;
}

std::unique_ptr<GlContext> createContext(BackendChoice choice, std::string& error) {
    using Factory = std::unique_ptr<GlContext> (*)(std::string&);
    std::vector<Factory> order;
    switch (choice) {
    case BackendChoice::Auto:
        order = {createEglDeviceContext, createOsMesaContext, createEglSurfacelessContext};
        break;
    case BackendChoice::OsMesa: order = {createOsMesaContext}; break;
    case BackendChoice::Egl: order = {createEglDeviceContext, createEglSurfacelessContext}; break;
    case BackendChoice::EglDevice: order = {createEglDeviceContext}; break;
    case BackendChoice::EglSurfaceless: order = {createEglSurfacelessContext}; break;
    case BackendChoice::EglGles: order = {createEglGlesContext}; break;
    }
    std::string reasons;
    for (Factory make : order) {
        std::string why;
        if (auto c = make(why)) return c;
        reasons += (reasons.empty() ? "" : "; ") + why;
    }
    error = "no OpenGL context: " + reasons;
    return nullptr;
}

}  // namespace glimmer
