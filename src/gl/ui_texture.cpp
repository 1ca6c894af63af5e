#include "gl/ui_texture.h"

#include "gl/gl_api.h"

namespace glimmer {

UiTexture::UiTexture() : gl_(std::make_unique<GlApi>()) {}

UiTexture::~UiTexture() {
    if (id_) gl_->DeleteTextures(1, &id_);
}

std::unique_ptr<UiTexture> UiTexture::create(const GetProcAddress& getProc, std::string& error) {
    std::unique_ptr<UiTexture> t(new UiTexture());
    if (!loadGlApi(*t->gl_, getProc, error)) return nullptr;
    return t;
}

unsigned UiTexture::upload(const Image& img) {
    if (img.empty() || img.type != Image::Type::U8) return 0;
    if (!id_) gl_->GenTextures(1, &id_);
    gl_->BindTexture(GL_TEXTURE_2D, id_);
    // Drawn at 1:1: nearest keeps each texel one pixel, as in the PNG.
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.u8.data());
    gl_->BindTexture(GL_TEXTURE_2D, 0);
    return id_;
}

}  // namespace glimmer
