// A class list for `glimmer serve --roster FILE`: one student a line, the
// first comma-separated field their name (quoted as a spreadsheet writes
// it, "Lovelace, Ada"), an optional header line "name,...", blank lines
// skipped. Each named student gets their own link (links.csv).
#pragma once
#include <string>
#include <vector>

namespace glimmer {

// The names in `text` (read from `file`, named in messages); false with
// `error` in compiler style ("roster.csv:4:1: error: ...") for a name that
// is empty, longer than 60 bytes, holds a control character, or comes twice,
// or more than 2000 students.
bool parseRoster(const std::string& text, const std::string& file, std::vector<std::string>& names, std::string& error);

}  // namespace glimmer
