// JSON: every JSON text Glimmer writes (batch's --report lines, grading's
// grades.jsonl, tradeoff's PREFIX.json) and reads (grades.jsonl, for
// --resume and batch-merge) goes through nlohmann/json (Debian's
// nlohmann-json3-dev) and these few functions, so they all keep one set of
// rules:
//   - Non-finite numbers: JSON has none. NaN, +Inf and -Inf are written as
//     the strings "nan", "inf" and "-inf" (jsonNumber), and numberFromJson
//     reads them back as the same values. Strings, not null: a grading
//     record's PSNR is +Inf for a picture equal to the solution's, and
//     --resume and batch-merge must get that +Inf back; null would lose it
//     (and could not tell NaN from Inf). Any JSON reader takes the strings.
//   - Text is UTF-8. A string that is not valid UTF-8 (a path, a Latin-1
//     source line quoted in a diagnostic) is written with each bad byte as
//     U+FFFD; writing never throws. Reading decodes \u escapes to UTF-8
//     (surrogate pairs included) and refuses text that is not valid UTF-8.
//   - Keys stay in the order they were set in (ordered_json): people read
//     these lines too.
// Desktop only: the browser build does not link nlohmann. One JSON text of
// the page's is still written by hand, its Measure blurs rows
// (web/web_tradeoff.cpp, infinity as null); issue 38 asks for it to come here.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace glimmer {

using Json = nlohmann::ordered_json;

// `v` as a JSON value: a number, or "nan", "inf", "-inf" (above).
Json jsonNumber(double v);
// The same, rounded to `digits` significant digits first (0.912345, not
// 0.91234512345678): for measurements whose last digits are noise.
Json jsonNumber(double v, int digits);
// A number, or one of the three strings above, as a double; false for
// anything else (`out` untouched).
bool numberFromJson(const Json& v, double& out);

// `v` on one line, compact (a JSON Lines record; no newline at the end).
std::string jsonLine(const Json& v);
// `v` indented by two spaces, ending with a newline (a file of its own).
std::string jsonDocument(const Json& v);

// `text` as one JSON value. Never throws: false with `error` ("at column
// 21: syntax error while parsing object key - unexpected end of input;
// expected string literal") when it is not JSON.
bool parseJson(const std::string& text, Json& out, std::string& error);

}  // namespace glimmer
