// A frame drawn in bands of rows, a budget of wall clock at a time, so the
// viewer's UI keeps answering while a heavy pass draws (issue 13: dragging
// the seed superblur's uHalfSize at 11 held the UI 640 ms per change on
// llvmpipe). Why bands under a scissor rather than anything cleverer:
// llvmpipe cannot be interrupted inside a draw, so the only way to bound
// the time one call takes is to give it less to draw; and the scissor
// changes which fragments are written, never what a fragment computes, so
// the finished frame is bit-identical to render() (tests/render/sliced_frame_test.cpp checks it).
#include "gl/renderer_internal.h"

namespace glimmer {

std::vector<bool> SlicedFrame::unfinished() const {
    std::vector<bool> out(only.size(), false);
    for (std::size_t p = pass; p < only.size() && !done; ++p) out[p] = only[p];
    return out;
}

SlicedFrame Renderer::startFrame(const UniformValues& values, double time, std::vector<bool> only) const {
    SlicedFrame f(values);
    if (plan_) only.resize(plan_->passes.size(), false);
    f.only = std::move(only);
    f.time = time;
    f.done = !plan_ || !screen_;
    return f;
}

bool Renderer::renderSlice(SlicedFrame& f, double budgetMs) {
    if (f.done || !plan_ || !screen_) return f.done = true;
    using Clock = std::chrono::steady_clock;
    msPerRow_.resize(plan_->passes.size(), 0.0);
    // What the UI drew since the last slice is not this frame's to pay for.
    finish();
    const auto sliceStart = Clock::now();
    auto spentMs = [&] { return std::chrono::duration<double, std::milli>(Clock::now() - sliceStart).count(); };
    bool drewABand = false;
    while (f.pass < plan_->passes.size()) {
        const Pass& pass = plan_->passes[f.pass];
        if (!pass.needed || !f.only[f.pass]) {
            ++f.pass;
            continue;
        }
        const double left = budgetMs - spentMs();
        if (drewABand && left <= 0) break;
        Target* target = passTarget(pass);
        if (f.row == 0) {
            if (passListener_) passListener_(int(f.pass));
            f.passMs = 0;
        }
        // As many rows as the budget left allows at this pass's last measured
        // rate. The rate may be stale (a slider took uHalfSize from 1 to 11:
        // 100 times the work), so a pass's first band in a frame is at most
        // a sixteenth of its rows unless the whole pass measured under 1 ms.
        const int rowsLeft = target->height - f.row;
        const int sixteenth = std::max(1, target->height / 16);
        const double rate = msPerRow_[f.pass];
        int rows = sixteenth;
        if (rate > 0) {
            const double fit = std::max(left, 0.0) / rate;
            rows = fit >= rowsLeft ? rowsLeft : std::max(1, int(fit));
            if (f.row == 0 && rate * target->height >= 1.0) rows = std::min(rows, sixteenth);
        }
        rows = std::min(rows, rowsLeft);

        const auto bandStart = Clock::now();
        gl_->Enable(GL_SCISSOR_TEST);
        gl_->Scissor(0, f.row, target->width, rows);
        drawPass(pass, target, f.values, f.time);
        gl_->Disable(GL_SCISSOR_TEST);
        finish();  // the band's cost, and the budget, are wall clock (in the browser too: see finish())
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - bandStart).count();
        msPerRow_[f.pass] = ms / rows;
        f.passMs += ms;
        f.row += rows;
        drewABand = true;
        if (f.row >= target->height) {
            finishPass(pass);
            f.timings.push_back({int(f.pass), f.passMs});
            ++f.pass;
            f.row = 0;
        }
    }
    gl_->UseProgram(0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    f.done = f.pass >= plan_->passes.size();
    return f.done;
}

double Renderer::progress(const SlicedFrame& f) const {
    if (f.done || !plan_) return 1.0;
    // Each pass weighs its measured cost (a pass never measured weighs as
    // much as the dearest one that was, or 1 when none was).
    double fallback = 0;
    for (double r : msPerRow_) fallback = std::max(fallback, r);
    if (fallback <= 0) fallback = 1;
    double total = 0, drawn = 0;
    for (std::size_t p = 0; p < plan_->passes.size() && p < f.only.size(); ++p) {
        if (!plan_->passes[p].needed || !f.only[p]) continue;
        const Target* t = passTarget(plan_->passes[p]);
        const double perRow = p < msPerRow_.size() && msPerRow_[p] > 0 ? msPerRow_[p] : fallback;
        const double cost = perRow * t->height;
        total += cost;
        if (p < f.pass) drawn += cost;
        else if (p == f.pass) drawn += perRow * f.row;
    }
    f.progressShown = std::max(f.progressShown, total > 0 ? std::min(drawn / total, 0.999) : 0.999);
    return f.progressShown;
}

}  // namespace glimmer
