#include "gl/window_frame.h"

#include "gl/gl_api.h"

#include <vector>

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

std::uint64_t WindowFrame::hashRegion(int x, int y, int w, int h, int windowH) const {
    std::uint64_t hash = 1469598103934665603ull;
    if (w <= 0 || h <= 0 || w > 16384 || h > 16384) return hash;
    std::vector<unsigned char> rgba(size_t(w) * size_t(h) * 4);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_->ReadPixels(x, windowH - y - h, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (unsigned char c : rgba) hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

}  // namespace glimmer
