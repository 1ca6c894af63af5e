// The parse tree of a .glib script: a flat list of commands with their
// arguments, each carrying the place it was written. No OpenGL here.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "lang/commands.h"
#include "lang/diagnostics.h"

namespace glimmer {

struct Arg {
    enum class Kind {
        Number,  // 0.  .5  -1.  4.8. (malformed, read as a prefix with a warning)
        Word,    // a file name, program name, uniform name, `true`, ...
        Range,   // < ... >   slider range, bool
        Color,   // { ... }   colour
        Array,   // [ ... ]   vector / array constant, Triangles vertex
    };
    Kind kind = Kind::Number;
    SourceLoc loc;
    double number = 0;        // Kind::Number
    std::string text;         // the characters as written (Word and Number)
    std::vector<Arg> items;   // Range/Color/Array: Number or Word items

    bool isGroup() const { return kind == Kind::Range || kind == Kind::Color || kind == Kind::Array; }
};

struct Command {
    CommandKind kind = CommandKind::Unknown;
    std::string spelled;  // the command word as written, e.g. "RenderTargetTexture"
    SourceLoc loc;        // of the command word
    std::vector<Arg> args;
};

struct Script {
    std::string file;  // path as given by the user
    std::vector<Command> commands;
    std::uint64_t bytes = 0;  // what lexing and parsing were charged (lang/lexer.h): part of --max-memory
};

}  // namespace glimmer
