// Lexing and parsing in one call: text in, Script and diagnostics out.
#pragma once
#include <cstdint>
#include <string>

#include "lang/diagnostics.h"
#include "lang/script.h"

namespace glimmer {

// `file` is only used to label diagnostics and is stored in Script::file.
// With `maxBytes` > 0 (--max-memory), a script whose parsed form would take
// more is one error at the token that went past it, and no commands.
Script parseScript(const std::string& file, const std::string& text, Diagnostics& diags, std::uint64_t maxBytes = 0);

}  // namespace glimmer
