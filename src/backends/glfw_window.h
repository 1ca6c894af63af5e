// A window with a GL 3.3 compatibility context, through GLFW: the viewer's
// backend. Like the headless ones, it only makes the context.
#pragma once
#include <memory>
#include <string>

#include "backends/context.h"

struct GLFWwindow;

namespace glimmer {

class GlfwWindow : public GlContext {
public:
    static std::unique_ptr<GlfwWindow> open(int width, int height, const std::string& title, std::string& error);
    ~GlfwWindow() override;
    void* getProcAddress(const char* name) override;
    std::string name() const override { return "glfw"; }
    GLFWwindow* handle() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace glimmer
