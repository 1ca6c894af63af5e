// The Dear ImGui panel: one panel for every front end that has one
// (`glimmer view`'s window, the browser page). It calls ImGui only, never
// GL: the front end owns the window, its input and the context, begins the
// ImGui window the panel draws into, and renders ImGui's draw lists with
// its backend (Dear ImGui's own line between core and imgui_impl_*).
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/watch_picture.h"
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

// Notes where the item ImGui drew last is, under `name` (ViewerState::
// controlRects): what `where NAME` prints and what the panel tour
// (tests/data/panel_tour.txt) clicks, in both shells. Every control of the
// panel has a name; panel.cpp's comments say which. `frameWidth`: for a
// slider, field or list, the width of its frame (the item's own rectangle
// runs on over its label, where a click does nothing); 0: the whole item.
void rememberControl(ViewerState& s, const std::string& name, float frameWidth = 0);
// What the panel shows, as one line of `key=value` words (a space or '%' in
// a value written %20 / %25): the answer to the `panel` command, which the
// panel tour reads after each click in both shells. `range`: the watch's
// fixed range (none: its own); `loads`: scripts loaded so far.
std::string panelState(const ViewerState& s, const std::optional<WatchRange>& range, int loads);
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
