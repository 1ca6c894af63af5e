#include "view/view_keys.h"

namespace glimmer {
namespace {

// glman's and glslViewer's habits: space plays and pauses the Timer, 0
// puts the turned scene back, H hides the panel for a clean projection.
struct KeyRow {
    std::string_view key;
    KeyAction action;
};
constexpr KeyRow kKeys[] = {
    {"q", KeyAction::Quit},        {"Escape", KeyAction::Quit},     {" ", KeyAction::PlayPause},
    {"h", KeyAction::TogglePanel}, {"r", KeyAction::Reload},        {"0", KeyAction::ResetView},
    {"s", KeyAction::Save},        {"f", KeyAction::Fullscreen},
};

}  // namespace

KeyAction keyAction(std::string_view key) {
    char lower = key.size() == 1 && key[0] >= 'A' && key[0] <= 'Z' ? char(key[0] - 'A' + 'a') : 0;
    for (const KeyRow& row : kKeys)
        if (row.key == key || (lower && row.key.size() == 1 && row.key[0] == lower)) return row.action;
    return KeyAction::None;
}

bool applyStateKey(KeyAction action, ViewerState& s) {
    switch (action) {
    case KeyAction::PlayPause: s.playing = !s.playing; return true;
    case KeyAction::TogglePanel: s.panelShown = !s.panelShown; return true;
    case KeyAction::ResetView: resetView(s); return true;
    default: return false;
    }
}

}  // namespace glimmer
