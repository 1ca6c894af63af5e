// glimmer view: a window showing the script's picture with a Dear ImGui
// panel of its uniforms, reloading on every save of the script, its shaders
// and images, re-running only the passes a change reaches.
#pragma once
#include <string>
#include <vector>

#include "view/panel.h"

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

// The options checked before a window opens (view_options.cpp): 0 with the
// window's first picture size in w x h (--size, else the script's
// WindowSize, else 600x600), or the exit code after a usage error.
int checkViewOptions(const ViewOptions& options, int& w, int& h);

// What it holds between frames, and the panel drawing it: view/panel.h.

}  // namespace glimmer
