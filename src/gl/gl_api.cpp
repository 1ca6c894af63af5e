#include "gl/gl_api.h"

#include <cstring>

#include <fmt/format.h>

namespace glimmer {

bool loadGlApi(GlApi& gl, const GetProcAddress& getProc, std::string& error) {
    std::string missing;
#define GLIMMER_GL_LOAD(name)                                                 \
    gl.name = reinterpret_cast<decltype(gl.name)>(getProc("gl" #name));       \
    if (!gl.name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
    GLIMMER_GL_FUNCTIONS(GLIMMER_GL_LOAD)
    if (gl.GetString) {
        const char* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
        gl.es = version && std::strncmp(version, "OpenGL ES", 9) == 0;
    }
    if (!gl.es) {
        GLIMMER_GL_DESKTOP_FUNCTIONS(GLIMMER_GL_LOAD)
    }
#undef GLIMMER_GL_LOAD
#ifndef __EMSCRIPTEN__
    // A context that reports resets says so in its strategy (ARB_robustness,
    // core since 4.5 and ES 3.2); asking any other context for the status
    // would call a stub on some drivers.
    if (gl.GetIntegerv && gl.GetError) {
        GLint strategy = 0;
        gl.GetIntegerv(GL_RESET_NOTIFICATION_STRATEGY_ARB, &strategy);
        // Bounded: a lost context may report its error for ever (contextFailure).
        for (int k = 0; k < 64 && gl.GetError() != GL_NO_ERROR; ++k) {
        }
        if (strategy == GL_LOSE_CONTEXT_ON_RESET_ARB)
            for (const char* name : {"glGetGraphicsResetStatus", "glGetGraphicsResetStatusARB", "glGetGraphicsResetStatusKHR",
                                     "glGetGraphicsResetStatusEXT"})
                if (!gl.GetGraphicsResetStatus)
                    gl.GetGraphicsResetStatus = reinterpret_cast<decltype(gl.GetGraphicsResetStatus)>(getProc(name));
    }
#endif
    if (!missing.empty()) {
        error = "the OpenGL driver lacks " + missing;
        return false;
    }
    return true;
}

std::string contextFailure(const GlApi& gl, GLenum* refused) {
    if (refused) *refused = GL_NO_ERROR;
    std::string why;
    if (gl.GetGraphicsResetStatus) {
        switch (gl.GetGraphicsResetStatus()) {
        case GL_NO_ERROR: break;
        case GL_GUILTY_CONTEXT_RESET_ARB: why = "the GPU was reset while this script drew (the driver blames this script)"; break;
        case GL_INNOCENT_CONTEXT_RESET_ARB: why = "the GPU was reset by another process while this script drew"; break;
        default: why = "the GPU was reset while this script drew"; break;
        }
    }
    if (!gl.GetError) return why;
    for (int k = 0; k < 64; ++k) {  // a lost context may report its error for ever
        const GLenum e = gl.GetError();
        if (e == GL_NO_ERROR) break;
        if (!why.empty()) continue;
        if (e == GL_OUT_OF_MEMORY) why = "the GPU driver ran out of memory (GL_OUT_OF_MEMORY)";
        else if (e == 0x0507 /* GL_CONTEXT_LOST */) why = "the GL context was lost (GL_CONTEXT_LOST)";
        else if (refused && *refused == GL_NO_ERROR) *refused = e;
    }
    return why;
}

std::string refusedCallWarning(GLenum error) {
    const char* name = error == GL_INVALID_ENUM                    ? "GL_INVALID_ENUM"
                       : error == GL_INVALID_VALUE                 ? "GL_INVALID_VALUE"
                       : error == GL_INVALID_OPERATION             ? "GL_INVALID_OPERATION"
                       : error == GL_INVALID_FRAMEBUFFER_OPERATION ? "GL_INVALID_FRAMEBUFFER_OPERATION"
                                                                   : "an unknown error";
    return fmt::format("glimmer: warning: the OpenGL driver refused a call while drawing ({}, 0x{:04X}): "
                       "a step of the picture may be missing", name, error);
}

}  // namespace glimmer
