// glslang's info log -> diagnostics against the user's own text. Its forms:
//   ERROR: 0:12: 'name' : undeclared identifier
//   WARNING: 0:3: '#extension' : ...
//   ERROR: Linking vertex stage: Missing entry point: ...
//   ERROR: 2 compilation errors.  No code generated.     (a summary: dropped)
// glslang gives no column; the column is where the token it quotes stands on
// the user's line (under the user's spelling when the translation renamed
// it), else the line's first character.
#pragma once
#include <map>
#include <string>
#include <string_view>

#include "lang/diagnostics.h"

namespace glimmer {

struct GlslangLogContext {
    std::string file;                               // the user's file
    std::string_view userText;                      // its text, for columns
    const std::map<std::string, std::string>* renames = nullptr;  // new name -> the user's spelling
    std::string prefix;                             // put before each message (may be empty)
};

// Adds one diagnostic per message line; returns how many errors it added.
int mapGlslangLog(std::string_view log, const GlslangLogContext& context, Diagnostics& diags);

// The 1-based column of `token` on line `line` of `text`, as whole tokens
// of the lexer (never inside a longer word or operator, never in a
// comment); 0 when it is not there.
int columnOf(std::string_view text, int line, std::string_view token);

}  // namespace glimmer
