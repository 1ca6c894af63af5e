// A string as a JSON string literal: the one escaping every JSON line
// Glimmer writes (batch's report lines, the grading records) goes through.
#pragma once
#include <string>

namespace glimmer {

// `text` as a JSON string literal, quotes included: '"', '\\' and control
// characters escaped, everything else (UTF-8 included) as it is.
std::string jsonString(const std::string& text);

}  // namespace glimmer
