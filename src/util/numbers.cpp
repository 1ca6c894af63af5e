#include "util/numbers.h"

#include <cerrno>
#include <cmath>
#include <charconv>
#include <cstdlib>
#include <locale.h>

#include <fmt/format.h>

// libstdc++ (GCC 11 and later) has floating-point from_chars and to_chars
// and says so; Emscripten 3.1.6's libc++ has neither and does not.
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
#define GLIMMER_FLOAT_CHARCONV 1
#endif

namespace glimmer {
namespace detail {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }
bool startsWithNoCase(const char* p, const char* last, const char* word) {
    for (; *word; ++word, ++p)
        if (p == last || lower(*p) != *word) return false;
    return true;
}

double strtodC(const char* text, char** end) {
#if defined(__GLIBC__)
    // glibc's strtod reads the decimal point of LC_NUMERIC; the "C" locale's
    // own copy does not change under the caller.
    static locale_t c = newlocale(LC_ALL_MASK, "C", locale_t(0));
    if (c) return strtod_l(text, end, c);
#endif
    return std::strtod(text, end);  // musl (Emscripten): always '.'
}

}  // namespace

ParsedNumber parseDoubleFallback(const char* first, const char* last, double& value) {
    const char* p = first;
    if (p != last && *p == '-') ++p;
    // What from_chars takes after the sign: digits, a point and a digit,
    // inf, infinity, nan, nan(chars). Anything else (a space, '+', a lone
    // point) is invalid_argument, as there.
    bool special = startsWithNoCase(p, last, "inf") || startsWithNoCase(p, last, "nan");
    bool digits = p != last && (isDigit(*p) || (*p == '.' && p + 1 != last && isDigit(p[1])));
    if (!special && !digits) return {first, std::errc::invalid_argument};
    // The longest stretch strtod could read, copied so it ends in a NUL.
    // "0x..." is hexadecimal to strtod but the number 0 then 'x' to
    // from_chars: only the '0' is handed over.
    const char* q = p;
    if (digits && *p == '0' && p + 1 != last && lower(p[1]) == 'x') q = p + 1;
    else
        while (q != last && (isDigit(*q) || *q == '.' || *q == '+' || *q == '-' || *q == '(' || *q == ')' ||
                             *q == '_' || (lower(*q) >= 'a' && lower(*q) <= 'z')))
            ++q;
    std::string text(first, q);
    char* end = nullptr;
    errno = 0;
    double v = strtodC(text.c_str(), &end);
    if (end == text.c_str()) return {first, std::errc::invalid_argument};
    const char* stop = first + (end - text.c_str());
    // glibc says ERANGE for a subnormal result too; from_chars takes it.
    if (errno == ERANGE && (v == 0 || std::isinf(v))) return {stop, std::errc::result_out_of_range};
    value = v;
    return {stop, std::errc{}};
}

// fmt's "{}" gives the shortest digits that read back as the value, but
// picks fixed or scientific by its own thresholds (fixed up to 1e16, like
// JavaScript); to_chars picks whichever is shorter, fixed on a tie. So the
// digits and exponent are taken from fmt and both forms are written out.
std::string formatDoubleFallback(double value) {
    std::string shortest = fmt::format("{}", value);
    if (!std::isfinite(value)) return shortest;  // "inf", "-inf", "nan" as to_chars
    std::string sign, digits;
    size_t i = 0;
    if (shortest[0] == '-') sign = "-", i = 1;
    int pointAt = -1, exponent = 0;  // digits before the point in the text
    for (; i < shortest.size() && shortest[i] != 'e'; ++i) {
        if (shortest[i] == '.') pointAt = int(digits.size());
        else digits += shortest[i];
    }
    if (i < shortest.size()) exponent = std::atoi(shortest.c_str() + i + 1);
    if (pointAt < 0) pointAt = int(digits.size());
    // value = 0.d1d2d3... x 10^(pointAt + exponent): drop leading zeros.
    int lead = 0;
    while (lead + 1 < int(digits.size()) && digits[lead] == '0') ++lead;
    digits.erase(0, lead);
    pointAt -= lead;
    while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
    if (digits == "0") return sign + "0";
    int e = pointAt + exponent - 1;  // scientific exponent of the first digit
    int n = int(digits.size());
    std::string sci = digits.substr(0, 1) + (n > 1 ? "." + digits.substr(1) : "") + (e < 0 ? "e-" : "e+") +
                      (std::abs(e) < 10 ? "0" : "") + std::to_string(std::abs(e));
    std::string fixed;
    // A whole number in fixed form is written exactly, as printf's %.0f
    // would (to_chars does): 13109662831590318080, not ...318000. Its
    // length is the same, so the choice below is not changed by it.
    if (e >= n - 1) fixed = fmt::format("{:.0f}", std::fabs(value));
    else if (e >= 0) fixed = digits.substr(0, size_t(e + 1)) + "." + digits.substr(size_t(e + 1));
    else fixed = "0." + std::string(size_t(-e - 1), '0') + digits;
    return sign + (sci.size() < fixed.size() ? sci : fixed);
}

}  // namespace detail

ParsedNumber parseDouble(const char* first, const char* last, double& value) {
#ifdef GLIMMER_FLOAT_CHARCONV
    auto [ptr, ec] = std::from_chars(first, last, value);
    return {ptr, ec};
#else
    return detail::parseDoubleFallback(first, last, value);
#endif
}

std::string formatDouble(double value) {
#ifdef GLIMMER_FLOAT_CHARCONV
    char buf[64];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc{} ? std::string(buf, ptr) : std::string("?");
#else
    return detail::formatDoubleFallback(value);
#endif
}

}  // namespace glimmer
