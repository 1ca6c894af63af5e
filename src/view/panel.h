// The Dear ImGui panel: one panel for every front end that has one
// (`glimmer view`'s window, the browser page). It calls ImGui only, never
// GL: the front end owns the window, its input and the context, begins the
// ImGui window the panel draws into, and renders ImGui's draw lists with
// its backend (Dear ImGui's own line between core and imgui_impl_*).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "view/viewer_state.h"

namespace glimmer {

// The "name = value" lines of the overlay, the same in the window and in a
// saved PNG.
std::string overlayText(const ViewerState& s);

// Draws the panel (an ImGui window already begun by the caller); returns
// the commands its buttons asked for. `thumbnails`: each render target's GL
// texture name for ImGui's backend to draw, 0 where none.
std::vector<ViewCommand> drawPanel(ViewerState& s, const std::vector<std::pair<int, unsigned>>& thumbnails);

// The panel as a window of its own, docked at x = `x` from the top, `height`
// tall, as wide as its content: begins it, draws the panel with a
// thumbnail of every render target, ends it. `width`, `contentHeight`: what
// it measured, for the front end's layout (view/view_model.h layoutWindow).
std::vector<ViewCommand> drawPanelWindow(ViewerState& s, float x, float height, int& width, int& contentHeight);

// The panel's text size at scale 1, in pixels (the "Show values" box's too).
constexpr float kPanelFontPx = 15;

// The ImGui fonts, at `scale`: DejaVu Sans (the panel) and DejaVu Sans Mono
// (error messages, whose carets must line up). Falls back to ImGui's own
// font scaled, with a warning on stderr, when no TTF file is found.
void setUpFonts(float scale);
// The scale the fonts were last made at (0 before the first setUpFonts):
// the ImGui context's, which outlives a viewer core (the page opens
// another script in the same context).
float fontsScale();

}  // namespace glimmer
