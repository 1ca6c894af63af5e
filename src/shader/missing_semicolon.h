// A statement without its ';' is reported by every GLSL compiler on the line
// after it, where the next statement starts: Mesa's "syntax error, unexpected
// NEW_IDENTIFIER, expecting ',' or ';'", glslang's "... expecting COMMA or
// SEMICOLON". A student then looks at a line that is right. As clang does,
// the place to point at is the end of the line the statement ends on; the
// driver's own place becomes a note ("the next statement starts here").
// Pure text: used for the desktop's driver logs (gl/compiler_log.cpp) and
// the page's glslang log (shader/glslang_log.cpp).
#pragma once
#include <optional>
#include <string_view>

#include "lang/diagnostics.h"

namespace glimmer {

// Where the ';' is missing, when `message` (at `line`, 1-based, of `text`)
// says one was expected and the nearest code line before it (blank lines,
// `//` comments and their tails skipped) ends without ';', '{', '}', ',' or
// '(' and is not a preprocessor line: that line, and the column just past
// its last character. Otherwise nothing (the driver's place stands).
std::optional<SourceLoc> missingSemicolonAt(std::string_view message, std::string_view text, int line);

}  // namespace glimmer
