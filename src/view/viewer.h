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
    std::string error;                       // the last failed reload's diagnostics, printed
    bool drawAll = true;                     // next frame runs every needed pass

    int shownTexture = -1;  // -1: the screen; else a target texture to inspect
    bool showValues = false;
    bool playing = true;
    double time = 0, drawnTime = -1;
    int hardcopy[2] = {1920, 1080};
    std::vector<PassTiming> lastTimings;
    std::vector<TargetHealth> health;  // measured now and then after drawing (a read-back of every target)
    double lastFrameMs = 0;
    std::string status;  // a one-line message for the panel (saved ..., reloaded ...)

    // glman's mouse: drag to turn the scene, scroll to zoom; kept out of the
    // script's ModelView matrix (see Renderer::setSceneTransform).
    float yaw = 0, pitch = 0, zoom = 1;
    bool sceneMoved = false;
};

// The "name = value" lines of the overlay, the same in the window and in a
// saved PNG.
std::string overlayText(const ViewerState& s);

// Draws the panel; returns the commands its buttons asked for.
std::vector<ViewCommand> drawPanel(ViewerState& s);

}  // namespace glimmer
