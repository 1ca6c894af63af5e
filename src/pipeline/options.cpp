#include "pipeline/options.h"

#include <charconv>

namespace glimmer {

bool parseSize(const std::string& text, int& w, int& h) {
    auto x = text.find_first_of("xX");
    if (x == std::string::npos) return false;
    auto num = [](const std::string& s, int& v) {
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        return ec == std::errc() && end == s.data() + s.size() && v >= 1 && v <= 16384;
    };
    return num(text.substr(0, x), w) && num(text.substr(x + 1), h);
}

}  // namespace glimmer
