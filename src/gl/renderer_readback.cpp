// Reading pictures back from the GPU: the screen and any texture, row 0 at
// the top as every CPU-side image is.
#include "gl/renderer_internal.h"

#include <fmt/format.h>

namespace glimmer {
using namespace renderer_detail;

Image Renderer::readScreen() const {
    if (!screen_) return {};
    return readPicture(*gl_, screen_->fbo, screen_->width, screen_->height);
}

std::string Renderer::contextFailure(std::string* refused) const {
    GLenum error = GL_NO_ERROR;
    std::string why = glimmer::contextFailure(*gl_, &error);
    if (refused) *refused = error == GL_NO_ERROR ? "" : refusedCallWarning(error);
    return why;
}

Image Renderer::readTextureFloat(int texture) const {
    if (texture < 0 || size_t(texture) >= textures_.size() || !textures_[size_t(texture)].id) return {};
    const TextureObject& t = textures_[size_t(texture)];
    if (t.target != GL_TEXTURE_2D) return {};
    // OpenGL ES reads an 8-bit target only as bytes (GL_FLOAT is an error
    // there and leaves zeros): read those, and give them as floats.
    if (gl_->es && !t.floatData) {
        Image bytes = readTexture(texture);
        Image img = Image::rgbaF32(bytes.width, bytes.height);
        for (size_t i = 0; i < bytes.u8.size() && i < img.f32.size(); ++i) img.f32[i] = bytes.u8[i] / 255.f;
        return img;
    }
    Image img = Image::rgbaF32(t.width, t.height);
    gl_->BindTexture(GL_TEXTURE_2D, t.id);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
    if (gl_->es) readThroughFramebuffer(*gl_, t.id, t.width, t.height, GL_FLOAT, img.f32.data());
    else gl_->GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, img.f32.data());
    gl_->BindTexture(GL_TEXTURE_2D, 0);
    img.f32 = flipRows(img.f32, img.height);
    return img;
}

bool Renderer::isFloatTexture(int texture) const {
    return texture >= 0 && size_t(texture) < textures_.size() && textures_[size_t(texture)].floatData;
}

std::vector<int> Renderer::renderTargets() const {
    std::vector<int> out;
    if (!plan_) return out;
    for (const auto& p : plan_->passes)
        if (p.needed)
            for (int t : p.targets)
                if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
    return out;
}

Image Renderer::readTexture(int texture) const {
    if (texture < 0 || size_t(texture) >= textures_.size() || !textures_[size_t(texture)].id) return {};
    const TextureObject& t = textures_[size_t(texture)];
    if (t.target != GL_TEXTURE_2D) return {};  // 3-D textures and cube maps are not pictures
    if (gl_->es && t.floatData) {
        // OpenGL ES reads a float target only as floats (as bytes it is an
        // error, and nothing is read): read those, and store them as the
        // desktop's glGetTexImage does, clamped to 0..1 and rounded.
        Image floats = readTextureFloat(texture);
        Image img = Image::rgba8(floats.width, floats.height);
        for (size_t i = 0; i < floats.f32.size() && i < img.u8.size(); ++i) {
            float v = floats.f32[i];
            img.u8[i] = static_cast<unsigned char>(std::nearbyint((v > 0 ? (v < 1 ? v : 1.f) : 0.f) * 255.f));
        }
        return img;
    }
    Image img = Image::rgba8(t.width, t.height);
    gl_->BindTexture(GL_TEXTURE_2D, t.id);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
    if (gl_->es) readThroughFramebuffer(*gl_, t.id, t.width, t.height, GL_UNSIGNED_BYTE, img.u8.data());
    else gl_->GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.u8.data());
    gl_->BindTexture(GL_TEXTURE_2D, 0);
    return flipRows(std::move(img));
}

}  // namespace glimmer
