// The viewer's scripting commands, one a line on standard input or
// separated by ';' in --exec: they make the window scriptable and testable.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace glimmer {

struct ViewCommand {
    enum class Kind { Set, Reload, Save, Show, Values, Probe, Split, Watch, Where, Panel, Scale, Help, Frames, Quit };
    Kind kind = Kind::Quit;
    std::string name;   // Set: the uniform; Save: the file; Where: the panel's control
    double value = 0;   // Set: the first number; Scale: the scale
    std::string text;   // Set: the value as written: a number, true/false, or "r,g,b[,a]" / a vector;
                        // Watch: FILE:LINE EXPR, "off", or with name "range": LO,HI or "auto"
    int unit = -1;      // Show, Split's left side: texture unit, -1 for the screen
    int right = -1;     // Split's right side: texture unit, -1 for the screen
    bool on = true;     // Values, Probe, Split: on or off
    bool report = false;  // Probe with no argument or at X Y: print what the probe reads
    int x = -1, y = -1;   // Probe X Y: that pixel of the picture (top row 0), not the pointer's
    // It only prints (help, frames, where, panel): the viewer does not count it as the user at work.
    bool onlyAsks() const { return kind == Kind::Help || kind == Kind::Frames || kind == Kind::Where || kind == Kind::Panel; }
};

// Parses one command; nullopt and `error` for anything else. Blank lines
// and lines starting with '#' give nullopt with an empty error.
std::optional<ViewCommand> parseViewCommand(const std::string& line, std::string& error);

// Splits an --exec argument at ';'.
std::vector<std::string> splitCommands(const std::string& text);

}  // namespace glimmer
