// Lexing and parsing in one call: text in, Script and diagnostics out.
#pragma once
#include <string>

#include "lang/diagnostics.h"
#include "lang/script.h"

namespace glimmer {

// `file` is only used to label diagnostics and is stored in Script::file.
Script parseScript(const std::string& file, const std::string& text, Diagnostics& diags);

}  // namespace glimmer
