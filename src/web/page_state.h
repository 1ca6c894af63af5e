// What the page's entry points share (page_check.cpp, web_render.cpp,
// web_view.cpp, web_view_input.cpp): one WebGL 2 context on #canvas for the
// page's life, the last picture handed to the page, the last diagnostics.
#pragma once
#include <string>
#include <vector>

#include "backends/context.h"
#include "image/image.h"

namespace glimmer_web {

// The page's context, made on first use and current from then on; null
// when the browser has no WebGL 2 (the reason in `why`).
glimmer::GlContext* pageContext(std::string* why = nullptr);

// The picture glimmer_pixels hands to the page (a render, a save, a hardcopy).
glimmer::Image& pagePicture();

// What glimmer_last_output() returns: diagnostics as the desktop prints them.
void setLastOutput(std::string text);

// "NAME=VALUE;NAME=VALUE" -> the --set entries.
std::vector<std::string> splitSets(const std::string& text);

// The live viewer (web_view.cpp), for the input, in the canvas's pixels:
// whether a point is on the picture (shown at the page's scale); glman's
// mouse on it (the core's pointer: a drag turns, the wheel zooms, the
// split's divider moves), a button let go anywhere, and whether the shown
// scene turns at all (the wheel scrolls the page otherwise). Each does
// nothing when no script is open.
bool pointerOverPicture(float x, float y);
bool viewerPointer(float x, float y, bool down, float wheel, bool captured);
void viewerLetGo();
bool viewerTurns();
// The panel's keys on the canvas (its buttons name them): R reload, S save,
// space pause or play, 0 the view reset. True when `key` (DOM's
// KeyboardEvent.key) is one; its effect comes with the next frame.
bool viewerKey(const char* key);
// Listens to the canvas's mouse, wheel and keys for ImGui and the
// picture (web_view_input.cpp). Once.
void setUpCanvasInput();

}  // namespace glimmer_web
