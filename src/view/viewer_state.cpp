#include "view/viewer_state.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/fold_diagnostics.h"
#include "view/view_model.h"

namespace glimmer {

// What `glimmer check` prints (pipeline/fold_diagnostics.h): a warning
// repeated in kind is one line, so the panel's count is the terminal's and
// the page's (issue 39: the seed's five uniforms on lines of their own made
// the panel say 6 warnings where the page said 2). Every error is its own
// entry, as before (no cascades folded: the panel lists each to click).
// A note is listed with the warnings and not counted (ViewerState::Message).
void keepMessages(ViewerState& s, const Diagnostics& diags, const SourceTexts& sources) {
    s.errors.clear();
    s.warnings.clear();
    size_t notShown = 0;
    for (FoldedDiagnostic& e : foldDiagnosticEntries(diags.all(), sources, true, false, true, SIZE_MAX, notShown))
        (e.severity == Severity::Error ? s.errors : s.warnings)
            .push_back({std::move(e.text), std::move(e.where), e.severity == Severity::Note});
}

size_t warningCount(const ViewerState& s) {
    return size_t(std::count_if(s.warnings.begin(), s.warnings.end(), [](const ViewerState::Message& m) { return !m.note; }));
}

bool adoptScript(ViewerState& s, LoadedScript next, std::unique_ptr<Renderer> renderer,
                 const std::vector<std::string>& sets, Diagnostics& diags) {
    UniformValues values(next.plan);
    if (s.good && s.values) values.carryOver(s.good->plan, *s.values, next.plan);
    else
        for (const auto& a : sets) values.applySet(next.plan, a, diags);
    bool first = !s.good;
    s.good = std::move(next);
    s.drawing = -1;
    s.renderer = std::move(renderer);
    s.values = values;
    s.drawnWith.reset();
    s.failed = false;
    s.drawAll = true;
    s.pictureW = s.good->plan.width;
    s.pictureH = s.good->plan.height;
    if (first || s.hardcopyAspect) sizeWithAspect(s.pictureW, s.pictureH, 1920, s.hardcopy[0], s.hardcopy[1]);
    s.turns = sceneTurns(s.good->plan);
    if (!s.turns) resetView(s);
    if (s.shownTexture >= int(s.good->plan.textures.size())) s.shownTexture = -1;
    return first;
}

glm::mat4 sceneMatrix(const ViewerState& s) {
    glm::mat4 m = glm::scale(glm::mat4(1.f), glm::vec3(s.zoom));
    m = glm::rotate(m, glm::radians(s.pitch), glm::vec3(1, 0, 0));
    return glm::rotate(m, glm::radians(s.yaw), glm::vec3(0, 1, 0));
}

void resetView(ViewerState& s) {
    s.yaw = s.pitch = 0;
    s.zoom = 1;
    s.sceneMoved = true;
}

Change changeSinceDrawn(const ViewerState& s, bool timeToo) {
    Change change;
    change.everything = s.drawAll;
    change.screen = s.sceneMoved;
    if (s.drawnWith && s.values) change.programs = s.values->programsDifferingFrom(*s.drawnWith);
    if (timeToo && s.renderer && s.good && s.time != s.drawnTime)
        for (size_t p = 0; p < s.good->plan.programs.size(); ++p)
            if (s.renderer->usesTimer(int(p))) change.programs.insert(int(p));
    return change;
}

bool pointerOnPicture(ViewerState& s, PictureDrag& drag, double x, double y, bool down, float wheel, bool captured,
                      int px, int py, int pw, int ph) {
    bool over = x >= px && x < px + pw && y >= py && y < py + ph && !captured;
    if (s.compare) {  // the divider follows a drag
        if (down && (drag.dragging || over)) s.divider = std::clamp(float((x - px) / std::max(pw, 1)), 0.f, 1.f);
        drag.dragging = down && (drag.dragging || over);
    } else {
        if (down && drag.dragging && s.turns) {
            s.yaw += float(x - drag.lastX) * 0.4f;
            s.pitch += float(y - drag.lastY) * 0.4f;
            s.sceneMoved = true;
        }
        drag.dragging = down && (drag.dragging || over);
        if (over && s.turns && wheel != 0) {
            s.zoom = std::clamp(s.zoom * std::pow(1.1f, wheel), 0.05f, 20.f);
            s.sceneMoved = true;
        }
    }
    drag.lastX = x;
    drag.lastY = y;
    if (s.renderer) s.renderer->setSceneTransform(sceneMatrix(s));
    return over;
}

void presentPicture(const ViewerState& s, int windowHeight, int x, int y, int w, int h) {
    if (!s.renderer) return;
    if (s.compare) {
        float d = std::clamp(s.divider, 0.f, 1.f);
        s.renderer->presentIn(s.compareLeft, windowHeight, x, y, w, h, 0.f, d);
        s.renderer->presentIn(s.compareRight, windowHeight, x, y, w, h, d, 1.f);
    } else {
        s.renderer->presentIn(s.watch ? Renderer::kWatchPicture : s.shownTexture, windowHeight, x, y, w, h);
    }
}

}  // namespace glimmer
