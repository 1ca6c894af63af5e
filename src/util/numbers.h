// Number text to double and back, independent of the locale and the same on
// every platform Glimmer builds for.
//
// Why not std::from_chars / std::to_chars directly: they are exactly right
// (locale-independent, shortest round trip) but the libc++ of Emscripten
// 3.1.6 (Debian's, for the browser build) has neither for floating point.
// Where the standard library has them they are used; elsewhere a fallback
// with the same contract: strtod behind a check that refuses what
// from_chars refuses (leading spaces, '+', hexadecimal), and fmt's shortest
// round-trip formatting. tests/util checks the fallback against the
// standard functions on the desktop build.
#pragma once
#include <string>
#include <system_error>

namespace glimmer {

struct ParsedNumber {
    const char* end;  // one past the last character used; `first` if none
    std::errc ec;     // {}, invalid_argument, or result_out_of_range (value untouched)
};

// std::from_chars(first, last, value) with chars_format::general.
ParsedNumber parseDouble(const char* first, const char* last, double& value);
// std::to_chars(buf, value): the shortest text that reads back as `value`.
std::string formatDouble(double value);

namespace detail {
// The fallbacks, compiled everywhere so the desktop tests can compare them
// with the standard functions.
ParsedNumber parseDoubleFallback(const char* first, const char* last, double& value);
std::string formatDoubleFallback(double value);
}  // namespace detail

}  // namespace glimmer
