#include "backends/glfw_window.h"

#include <GLFW/glfw3.h>

#include "backends/driver_shader_cache.h"

namespace glimmer {

std::unique_ptr<GlfwWindow> GlfwWindow::open(int width, int height, const std::string& title, std::string& error) {
    disableMesaShaderCache();  // before GLX loads the driver: logs must not depend on an earlier run
    if (!glfwInit()) {
        error = "cannot start GLFW (is there a display? try xvfb-run)";
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    // glman's shaders need the compatibility profile.
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_COMPAT_PROFILE);
    std::unique_ptr<GlfwWindow> w(new GlfwWindow());
    w->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!w->window_) {
        error = "cannot open a window with an OpenGL 3.3 compatibility context";
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(w->window_);
    glfwSwapInterval(1);
    return w;
}

GlfwWindow::~GlfwWindow() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

void* GlfwWindow::getProcAddress(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

}  // namespace glimmer
