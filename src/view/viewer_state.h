// What a viewer holds between frames, and the steps every viewer takes on
// it: the desktop window (view/viewer.cpp) and the browser page
// (web/web_view.cpp) each keep one ViewerState, fill it the same way and
// draw it with the one panel (view/panel.h). No window, no GL calls here.
#pragma once
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "pipeline/load_script.h"
#include "pipeline/numeric_health.h"
#include "pipeline/watch.h"
#include "gl/renderer.h"
#include "plan/dependencies.h"
#include "plan/uniform_values.h"
#include "view/view_commands.h"

namespace glimmer {

// What a viewer holds between frames: the desktop window (view/viewer.cpp)
// and the page (web/web_view.cpp) keep one each and draw it with the panel.
struct ViewerState {
    // The last script that loaded without errors, and its renderer: a broken
    // edit never replaces them.
    std::optional<LoadedScript> good;
    std::unique_ptr<Renderer> renderer;
    std::optional<UniformValues> values;     // what the sliders say now
    std::optional<UniformValues> drawnWith;  // what the picture was drawn with
    // The last failed reload: errors first (each with its file:line), then
    // warnings, kept apart so the panel folds the warnings into a count.
    struct Message {
        std::string text;   // formatted, clang style, with the source line and caret
        std::string where;  // "file:line" to copy
        bool note = false;  // a note (listed with the warnings, not counted)
    };
    std::vector<Message> errors, warnings;
    bool failed = false;
    bool drawAll = true;                     // next frame runs every needed pass

    int shownTexture = -1;  // -1: the screen; else a target texture to inspect
    bool showValues = false;
    bool playing = true;
    double time = 0, drawnTime = -1;
    int hardcopy[2] = {1920, 1920};  // set to the picture's aspect when a script loads
    bool hardcopyAspect = true;       // keep the picture's aspect when the width is typed
    int pictureW = 0, pictureH = 0;   // the picture's size (the plan's)
    bool panelShown = true;
    std::vector<std::string> splitUniforms;  // merged uniforms the user split per Program again
    // Teaching aids: a before/after split of two textures (-1: the screen)
    // at a divider the user drags, and a probe of the value under the pointer.
    bool compare = false;
    int compareLeft = -1, compareRight = -1;
    float divider = 0.5f;
    // Off until asked for (the panel's checkbox): its tooltip follows the
    // pointer over the picture, which a class watching the picture does not want by default.
    bool probe = false;
    std::string probeText;  // what the probe read at the pointer, for the panel
    // A watch (pipeline/watch.h): one expression's value over its pass,
    // shown instead of the picture while on, drawn again as sliders move and
    // set up again on every reload. The panel's field, the watch's one-line
    // summary, and why the last watch asked for was refused.
    std::optional<Watch> watch;
    std::string watchSpec, watchSummary, watchError;
    std::vector<PassTiming> lastTimings;
    std::vector<TargetHealth> health;  // measured now and then after drawing (a read-back of every target)
    double lastFrameMs = 0;  // the last finished picture's drawing time, all its passes
    float drawing = -1;      // how much of a picture under way is drawn (0 to 1); -1: none
    std::string status;  // a one-line message for the panel (saved ..., reloaded ...)
    std::string keyHint;  // the front end's own keys, a line under the buttons ("" for none)
    // Where each uniform's control was drawn in the last frame (x, y, w, h
    // in window pixels): what a test or a script clicks (web_view.cpp).
    std::map<std::string, std::array<float, 4>> controlRects;
    // The named control ImGui held active in the last frame ("" none): a
    // field that has the keyboard, a button held down, a slider dragged.
    // `panel` says it (active=), so a test that clicks a field knows the
    // click took before it types (a slow frame can lose a click).
    std::string activeControl;
    float panelMaxW = 0;  // > 0: the shell pins the panel's width (the page): text wraps inside it

    // glman's mouse: drag to turn the scene, scroll to zoom; kept out of the
    // script's ModelView matrix (see Renderer::setSceneTransform).
    float yaw = 0, pitch = 0, zoom = 1;
    bool sceneMoved = false;
    bool turns = false;  // sceneTurns(plan): the mouse turns and zooms only scenes where it means something
};

// The diagnostics of a load, kept for the panel: errors first, each with
// its "file:line", warnings apart (the panel folds them into a count).
void keepMessages(ViewerState& s, const Diagnostics& diags, const SourceTexts& sources);
// The warnings the panel lists, notes left out: its count.
size_t warningCount(const ViewerState& s);

// A script that loaded without errors replaces the last good one: the
// slider values carry over by name from the script before (the first
// script takes `sets`, --set's NAME=VALUE entries), and the next frame
// draws every pass. Returns whether it was the viewer's first script.
bool adoptScript(ViewerState& s, LoadedScript next, std::unique_ptr<Renderer> renderer,
                 const std::vector<std::string>& sets, Diagnostics& diags);

// glman's mouse: the scene turned by yaw and pitch and scaled by zoom, kept
// apart from the script's own ModelView (Renderer::setSceneTransform).
glm::mat4 sceneMatrix(const ViewerState& s);
void resetView(ViewerState& s);

// What changed since the picture was drawn: everything after a load, the
// screen after the mouse turned it, the Programs whose sliders moved, and
// with `timeToo` the Programs reading Timer when the time moved. The
// passes to draw are then passesToRun(plan, change).
Change changeSinceDrawn(const ViewerState& s, bool timeToo);

// glman's mouse on the picture at x, y, w, h (window pixels, y down): a
// drag turns the scene, the wheel zooms it (only where sceneTurns), and in
// the before/after split a drag moves the divider. `captured`: the panel
// has the pointer (ImGui's WantCaptureMouse). Returns whether the pointer
// is over the picture (for the probe).
struct PictureDrag {
    bool dragging = false;
    double lastX = 0, lastY = 0;
};
bool pointerOnPicture(ViewerState& s, PictureDrag& drag, double x, double y, bool down, float wheel, bool captured,
                      int px, int py, int pw, int ph);

// The shown picture (the screen or an inspected target, or the before/after
// split of two) into the rectangle x, y, w, h of a window `windowHeight`
// tall, through the renderer.
void presentPicture(const ViewerState& s, int windowHeight, int x, int y, int w, int h);

}  // namespace glimmer
