// What the viewer decides without a window or a context: whether the mouse
// may turn a scene, how the window is laid out, how passes and merged
// uniforms are named, which file a save writes, the help text. Plain
// functions of the plan, so test_view checks them without X.
#pragma once
#include <string>
#include <vector>

#include "plan/plan.h"

namespace glimmer {

// Whether dragging and the wheel mean something: some draw to the screen
// has a perspective projection or a shape that is not flat. A flat script
// (an Ortho full-screen quad, a post-process like the seed bloom) is never
// turned or zoomed, so what is shown and saved stays what `render` draws.
bool sceneTurns(const Plan& plan);

// "SuperBlur (line 12) -> unit 6", "Bloom (line 27) -> screen": a pass by the
// Program it draws with and the line where that Program is declared.
std::string passName(const Plan& plan, int pass);

// One control of the panel: a uniform of one Program, or a uniform of the
// same name, form and range in several Programs shown as one ("uOffset -
// 8 passes"; kawase's eight uOffset). Only Range, Bool and Color forms merge.
struct UniformControl {
    std::string name;
    std::vector<int> programs;  // one, or every Program it stands for (in plan order)
    const UniformSetting* setting = nullptr;  // of the first program
    std::string label() const;  // the name, with " - N passes" when merged
};
// Merged controls, in order of first appearance; `split` lists the names
// the user asked to see per Program again (they are left out here).
std::vector<UniformControl> mergedUniforms(const Plan& plan, const std::vector<std::string>& split = {});

// The first of STEM-001.EXT, STEM-002.EXT, ... that does not exist.
std::string nextFreeName(const std::string& stem, const std::string& ext);

// A hardcopy size with the picture's aspect: the longer side `longSide`.
void sizeWithAspect(int pictureW, int pictureH, int longSide, int& w, int& h);

// The window: the picture at its exact size at the top left, the panel
// docked to its right. The window is as tall as the taller of the two (the
// panel at most `maxHeight`).
struct WindowLayout {
    int windowW = 0, windowH = 0;
    int panelX = 0, panelW = 0;  // panelW 0: hidden
};
WindowLayout layoutWindow(int pictureW, int pictureH, bool panelShown, int panelW, int panelH, int maxHeight);

// The panel's scale: --ui-scale when given (non-zero), else the monitor's
// content scale as GLFW reports it (the larger of x and y; a HiDPI screen
// says 2), never below 1.
float chooseUiScale(double option, float monitorScaleX, float monitorScaleY);

// Every command and key, a line each (the `help` command prints it).
std::string helpText();

}  // namespace glimmer
