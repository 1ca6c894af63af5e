// The viewer's keys, one table for the window and the page (issue 25):
// each shell names a pressed key as the DOM does ("q", "Escape", " ",
// "0") and asks what it means; the state-only actions are applied here, the
// rest (reload, save, fullscreen, quit) by the shell, which alone can.
#pragma once
#include <string_view>

#include "view/viewer_state.h"

namespace glimmer {

enum class KeyAction { None, Quit, PlayPause, TogglePanel, Reload, ResetView, Save, Fullscreen };

// The action of the key named `key` (letters in either case); None for any other.
KeyAction keyAction(std::string_view key);

// Applies PlayPause, TogglePanel and ResetView to `s`; true when it did
// (the others are the shell's).
bool applyStateKey(KeyAction action, ViewerState& s);

}  // namespace glimmer
