// The page's input for the live viewer: the canvas's own mouse, touch, wheel
// and key events, handed to ImGui (1.86's io fields) and to glman's mouse on the
// picture (the viewer core's pointer, view/viewer_core.h).
//
// Why not Emscripten's GLFW port with imgui_impl_glfw, as on the desktop:
// that port listens for keys on the whole window and makes its own WebGL
// context on Module.canvas, so the page's code editor would lose keys to it
// and the renderer would need a second context. Listening on the canvas
// only keeps every other element of the page its own keyboard.
#include <emscripten/html5.h>
#include <imgui.h>

#include <cstring>

#include "web/page_state.h"

namespace {

// DOM KeyboardEvent.key -> ImGui's key, one row per key ImGui's text
// fields and navigation use (1.86 maps its keys through io.KeyMap).
struct KeyRow {
    const char* dom;
    ImGuiKey key;
};
constexpr KeyRow kKeys[] = {
    {"Tab", ImGuiKey_Tab},         {"ArrowLeft", ImGuiKey_LeftArrow}, {"ArrowRight", ImGuiKey_RightArrow},
    {"ArrowUp", ImGuiKey_UpArrow}, {"ArrowDown", ImGuiKey_DownArrow}, {"PageUp", ImGuiKey_PageUp},
    {"PageDown", ImGuiKey_PageDown}, {"Home", ImGuiKey_Home},         {"End", ImGuiKey_End},
    {"Insert", ImGuiKey_Insert},   {"Delete", ImGuiKey_Delete},       {"Backspace", ImGuiKey_Backspace},
    {" ", ImGuiKey_Space},         {"Enter", ImGuiKey_Enter},         {"Escape", ImGuiKey_Escape},
    {"a", ImGuiKey_A},             {"c", ImGuiKey_C},                 {"v", ImGuiKey_V},
    {"x", ImGuiKey_X},             {"y", ImGuiKey_Y},                 {"z", ImGuiKey_Z},
};

void mods(ImGuiIO& io, bool ctrl, bool shift, bool alt, bool meta) {
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    io.KeyAlt = alt;
    io.KeySuper = meta;
}

// The canvas's pixels per CSS pixel: the page sizes the canvas's backing
// store at devicePixelRatio (and the presentation mode's scale) and its
// box in CSS pixels, while events come in CSS pixels.
float canvasPixelsPerCssPixel() {
    int backingW = 0, backingH = 0;
    double cssW = 0, cssH = 0;
    if (emscripten_get_canvas_element_size("#canvas", &backingW, &backingH) != EMSCRIPTEN_RESULT_SUCCESS ||
        emscripten_get_element_css_size("#canvas", &cssW, &cssH) != EMSCRIPTEN_RESULT_SUCCESS || cssW <= 0)
        return 1.f;
    return float(backingW / cssW);
}

EM_BOOL onMouse(int type, const EmscriptenMouseEvent* e, void*) {
    ImGuiIO& io = ImGui::GetIO();
    const float k = canvasPixelsPerCssPixel();
    float x = float(e->targetX) * k, y = float(e->targetY) * k;
    io.MousePos = ImVec2(x, y);
    if (type == EMSCRIPTEN_EVENT_MOUSEDOWN && e->button < 3) io.MouseDown[e->button == 1 ? 2 : e->button == 2 ? 1 : 0] = true;
    if (type == EMSCRIPTEN_EVENT_MOUSEUP && e->button < 3) io.MouseDown[e->button == 1 ? 2 : e->button == 2 ? 1 : 0] = false;
    mods(io, e->ctrlKey, e->shiftKey, e->altKey, e->metaKey);
    glimmer_web::viewerPointer(x, y, io.MouseDown[0], 0.f, io.WantCaptureMouse);
    return type == EMSCRIPTEN_EVENT_MOUSEDOWN;  // no text selection starting on the canvas
}

// A button let go anywhere (a slider dragged past the canvas's edge).
EM_BOOL onRelease(int, const EmscriptenMouseEvent* e, void*) {
    if (e->button < 3) ImGui::GetIO().MouseDown[e->button == 1 ? 2 : e->button == 2 ? 1 : 0] = false;
    glimmer_web::viewerLetGo();
    return false;
}

// A finger on a Chromebook's or tablet's screen is the mouse's left
// button: the first touch moves the pointer and presses, moving drags a
// slider or turns the picture, lifting releases. The browser's own use of
// the touch (scrolling the page, a zoom) is kept off the canvas only while
// the finger is on the panel or the picture.
EM_BOOL onTouch(int type, const EmscriptenTouchEvent* e, void*) {
    if (e->numTouches < 1) return false;
    const EmscriptenTouchPoint& t = e->touches[0];
    ImGuiIO& io = ImGui::GetIO();
    const float k = canvasPixelsPerCssPixel();
    const float x = float(t.targetX) * k, y = float(t.targetY) * k;
    io.MousePos = ImVec2(x, y);
    const bool down = type == EMSCRIPTEN_EVENT_TOUCHSTART || type == EMSCRIPTEN_EVENT_TOUCHMOVE;
    io.MouseDown[0] = down;
    if (!down) glimmer_web::viewerLetGo();
    glimmer_web::viewerPointer(x, y, down, 0.f, io.WantCaptureMouse);
    return true;  // the canvas's own: no scroll, no synthesized mouse events after it
}

EM_BOOL onWheel(int, const EmscriptenWheelEvent* e, void*) {
    ImGuiIO& io = ImGui::GetIO();
    // A line is about 100 "pixels" of deltaY in Chromium; one wheel notch is one ImGui step.
    float steps = float(e->deltaMode == DOM_DELTA_PIXEL ? -e->deltaY / 100.0 : -e->deltaY);
    io.MouseWheel += steps;
    bool onPicture = glimmer_web::pointerOverPicture(io.MousePos.x, io.MousePos.y);
    if (onPicture) glimmer_web::viewerPointer(io.MousePos.x, io.MousePos.y, io.MouseDown[0], steps, io.WantCaptureMouse);
    return onPicture && glimmer_web::viewerTurns();  // the page scrolls unless the wheel zoomed a scene
}

EM_BOOL onKey(int type, const EmscriptenKeyboardEvent* e, void*) {
    ImGuiIO& io = ImGui::GetIO();
    mods(io, e->ctrlKey, e->shiftKey, e->altKey, e->metaKey);
    bool down = type == EMSCRIPTEN_EVENT_KEYDOWN;
    for (const KeyRow& row : kKeys)
        if (std::strcmp(e->key, row.dom) == 0) io.KeysDown[row.key] = down;
    // A printable key (one character in UTF-8, no Ctrl) types into a field.
    if (down && !e->ctrlKey && !e->metaKey && e->key[0] && std::strlen(e->key) <= 4 &&
        (std::strlen(e->key) == 1 || (unsigned char)e->key[0] >= 0x80))
        io.AddInputCharactersUTF8(e->key);
    // The panel's own keys, when no text field has the keyboard.
    if (down && !io.WantTextInput && !e->ctrlKey && !e->metaKey && !e->altKey && glimmer_web::viewerKey(e->key)) return true;
    return io.WantCaptureKeyboard;  // keys the panel used go no further
}

}  // namespace

namespace glimmer_web {

void setUpCanvasInput() {
    ImGuiIO& io = ImGui::GetIO();
    for (int k = 0; k < ImGuiKey_COUNT; ++k) io.KeyMap[k] = k;  // KeysDown is indexed by ImGui's own keys
    emscripten_set_mousedown_callback("#canvas", nullptr, false, onMouse);
    emscripten_set_mouseup_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, nullptr, false, onRelease);
    emscripten_set_mousemove_callback("#canvas", nullptr, false, onMouse);
    emscripten_set_wheel_callback("#canvas", nullptr, false, onWheel);
    emscripten_set_touchstart_callback("#canvas", nullptr, false, onTouch);
    emscripten_set_touchmove_callback("#canvas", nullptr, false, onTouch);
    emscripten_set_touchend_callback("#canvas", nullptr, false, onTouch);
    emscripten_set_touchcancel_callback("#canvas", nullptr, false, onTouch);
    emscripten_set_keydown_callback("#canvas", nullptr, false, onKey);
    emscripten_set_keyup_callback("#canvas", nullptr, false, onKey);
}

}  // namespace glimmer_web
