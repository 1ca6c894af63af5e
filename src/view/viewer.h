// glimmer view: a window showing the script's picture with a Dear ImGui
// panel of its uniforms, reloading on every save of the script, its shaders
// and images, re-running only the passes a change reaches.
#pragma once
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "driver/load_script.h"
#include "driver/numeric_health.h"
#include "backends/glfw_window.h"
#include "gl/renderer.h"
#include "plan/uniform_values.h"
#include "view/file_watch.h"
#include "view/view_commands.h"

namespace glimmer {

struct ViewOptions {
    std::string script;
    std::vector<std::string> includeDirs;
    std::vector<std::string> sets;
    std::string size;  // WxH; else WindowSize; else 600x600
    std::string exec;  // commands separated by ';'
    bool readStdin = true;
    bool standIns = true;  // missing images and models are replaced (assets/stand_ins.h)
    bool sandbox = false;  // --sandbox
    double uiScale = 0;  // --ui-scale; 0: the monitor's content scale (1 where GLFW reports none)
};

int runView(const ViewOptions& options);

// What the viewer holds between frames. Public so the panel can draw it.
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
    std::vector<PassTiming> lastTimings;
    std::vector<TargetHealth> health;  // measured now and then after drawing (a read-back of every target)
    double lastFrameMs = 0;  // the last finished picture's drawing time, all its passes
    float drawing = -1;      // how much of a picture under way is drawn (0 to 1); -1: none
    std::string status;  // a one-line message for the panel (saved ..., reloaded ...)

    // glman's mouse: drag to turn the scene, scroll to zoom; kept out of the
    // script's ModelView matrix (see Renderer::setSceneTransform).
    float yaw = 0, pitch = 0, zoom = 1;
    bool sceneMoved = false;
    bool turns = false;  // sceneTurns(plan): the mouse turns and zooms only scenes where it means something
};

// The "name = value" lines of the overlay, the same in the window and in a
// saved PNG.
std::string overlayText(const ViewerState& s);

// Draws the panel (an ImGui window already begun by the caller); returns
// the commands its buttons asked for. `thumbnails`: each render target's GL
// texture name for ImGui's backend to draw, 0 where none.
std::vector<ViewCommand> drawPanel(ViewerState& s, const std::vector<std::pair<int, unsigned>>& thumbnails);

// The ImGui fonts, at `scale`: DejaVu Sans (the panel) and DejaVu Sans Mono
// (error messages, whose carets must line up). Falls back to ImGui's own
// font scaled, with a warning on stderr, when no TTF file is found.
void setUpFonts(float scale);

}  // namespace glimmer
