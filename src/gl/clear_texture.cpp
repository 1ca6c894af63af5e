#include "gl/clear_texture.h"

namespace glimmer {

void clearTexture2D(const GlApi& gl, unsigned texture) {
    unsigned fbo = 0;
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    gl.Disable(GL_SCISSOR_TEST);
    gl.ClearColor(0.f, 0.f, 0.f, 0.f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &fbo);
}

}  // namespace glimmer
