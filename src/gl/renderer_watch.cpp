// Drawing a watch (issue 28, pipeline/watch.h): the passes that feed the
// watched pass as render() draws them, then that pass again into two float
// targets, with the rewritten program standing in for the watched one.
#include "gl/renderer_internal.h"

namespace glimmer {
using namespace renderer_detail;

bool Renderer::prepareWatch(int program, const std::map<size_t, std::string>& replaced, Diagnostics& diags) {
    dropWatch();
    if (!plan_ || program < 0 || size_t(program) >= programs_.size() || !programs_[size_t(program)]) return false;
    std::vector<std::optional<std::string>> texts = programs_[size_t(program)]->texts;
    for (const auto& [stage, text] : replaced)
        if (stage < texts.size()) texts[stage] = text;
    // The program's warnings were said when it was first built: only the
    // rewrite's errors are news.
    Diagnostics said;
    std::unique_ptr<Program> p = makeProgram(*plan_, plan_->programs[size_t(program)], texts, said);
    for (const Diagnostic& d : said.all())
        if (d.severity == Severity::Error) diags.add(d);
    if (!p) return false;
    watch_ = std::move(p);
    watchedProgram_ = program;
    return true;
}

void Renderer::dropWatch() {
    if (watch_ && watch_->id) gl_->DeleteProgram(watch_->id);
    watch_.reset();
    watchedProgram_ = -1;
}

void Renderer::uploadPicture(const Image& picture) {
    if (picture.type != Image::Type::U8 || picture.width < 1 || picture.height < 1) return;
    if (!uploaded_) {
        uploaded_ = std::make_unique<Target>();
        gl_->GenTextures(1, &uploadedTexture_);
        gl_->GenFramebuffers(1, &uploaded_->fbo);
    }
    gl_->BindTexture(GL_TEXTURE_2D, uploadedTexture_);
    textureParameters(*gl_);
    gl_->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, picture.width, picture.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    flipRows(picture.u8, picture.height).data());
    gl_->BindTexture(GL_TEXTURE_2D, 0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, uploaded_->fbo);
    gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, uploadedTexture_, 0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    uploaded_->width = picture.width, uploaded_->height = picture.height;
}

std::vector<std::optional<std::string>> Renderer::programTexts(int program) const {
    if (program < 0 || size_t(program) >= programs_.size() || !programs_[size_t(program)]) return {};
    return programs_[size_t(program)]->texts;
}

WatchCapture Renderer::renderWatch(int passIndex, const UniformValues& values, double time,
                                   const std::vector<bool>& feeding) {
    WatchCapture out;
    if (!watch_ || !plan_ || !screen_ || passIndex < 0 || size_t(passIndex) >= plan_->passes.size()) return out;
    std::vector<bool> before = feeding;
    if (size_t(passIndex) < before.size()) before[size_t(passIndex)] = false;
    render(values, time, nullptr, &before);

    const Pass& pass = plan_->passes[size_t(passIndex)];
    int width = plan_->width, height = plan_->height;
    if (!pass.targets.empty()) {
        const TextureDecl& t = plan_->textures[size_t(pass.targets.front())];
        width = t.width, height = t.height;
    }
    // Two float targets of the pass's size: the value, and what is known of it.
    Target target;
    target.width = width, target.height = height;
    unsigned textures[2] = {};
    gl_->GenTextures(2, textures);
    gl_->GenFramebuffers(1, &target.fbo);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, target.fbo);
    for (int k = 0; k < 2; ++k) {
        gl_->BindTexture(GL_TEXTURE_2D, textures[k]);
        gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D, textures[k], 0);
    }
    gl_->BindTexture(GL_TEXTURE_2D, 0);
    if (pass.needsDepth) target.depth = attachDepth(width, height);
    const bool complete = gl_->CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (complete) {
        bindForPass(target, 2, pass.needsDepth);
        const GLbitfield clear = GL_COLOR_BUFFER_BIT | (pass.needsDepth ? GL_DEPTH_BUFFER_BIT : 0);
        gl_->ClearColor(0, 0, 0, 0);  // nothing drawn: info x = 0
        gl_->Clear(clear);
        // The watched pass is announced as render() announces its passes, so
        // a --timeout names its line (issue 37: "while loading and
        // compiling", with no line).
        if (passListener_) passListener_(passIndex);
        std::swap(programs_[size_t(watchedProgram_)], watch_);
        for (const auto& s : pass.steps) {
            if (s.kind == Step::Kind::Clear) {
                gl_->Clear(clear);
                continue;
            }
            const bool watched = s.draw.program == watchedProgram_;
            if (!watched) gl_->ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            drawStep(s.draw, values, time, pass.targets);
            if (!watched) gl_->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        std::swap(programs_[size_t(watchedProgram_)], watch_);
        for (int k = 0; k < 2; ++k) {  // the value, then what is known of it; row 0 at the top
            Image& img = k ? out.info : out.value;
            img = Image::rgbaF32(width, height);
            gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
            readThroughFramebuffer(*gl_, textures[k], width, height, GL_FLOAT, img.f32.data());
            img.f32 = flipRows(img.f32, height);
        }
    }
    gl_->UseProgram(0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_->DeleteFramebuffers(1, &target.fbo);
    if (target.depth) gl_->DeleteRenderbuffers(1, &target.depth);
    gl_->DeleteTextures(2, textures);
    return out;
}

}  // namespace glimmer
