#include "gl/gl_api.h"

#include <cstring>

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
    if (!missing.empty()) {
        error = "the OpenGL driver lacks " + missing;
        return false;
    }
    return true;
}

}  // namespace glimmer
