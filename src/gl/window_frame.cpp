#include "gl/window_frame.h"

#include "gl/gl_api.h"

namespace glimmer {

WindowFrame::WindowFrame() : gl_(std::make_unique<GlApi>()) {}
WindowFrame::~WindowFrame() = default;

std::unique_ptr<WindowFrame> WindowFrame::create(const GetProcAddress& getProc, std::string& error) {
    std::unique_ptr<WindowFrame> f(new WindowFrame());
    if (!loadGlApi(*f->gl_, getProc, error)) return nullptr;
    return f;
}

void WindowFrame::begin(int width, int height, float r, float g, float b) const {
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_->Viewport(0, 0, width, height);
    gl_->ClearColor(r, g, b, 1.f);
    gl_->Clear(GL_COLOR_BUFFER_BIT);
}

}  // namespace glimmer
