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
    dropWatchTargets();
}

std::vector<std::optional<std::string>> Renderer::programTexts(int program) const {
    if (program < 0 || size_t(program) >= programs_.size() || !programs_[size_t(program)]) return {};
    return programs_[size_t(program)]->texts;
}

bool Renderer::renderWatch(int passIndex, const UniformValues& values, double time, const std::vector<bool>& feeding) {
    if (!watch_ || !plan_ || !screen_ || passIndex < 0 || size_t(passIndex) >= plan_->passes.size()) return false;
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
    if (!bindWatchTargets(width, height, pass.needsDepth)) return false;
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
    gl_->UseProgram(0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    watchGpu_->drawn = true;
    return true;
}

}  // namespace glimmer
