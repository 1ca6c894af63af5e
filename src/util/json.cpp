#include "util/json.h"

#include <cmath>

#include <fmt/format.h>

#include "util/numbers.h"

namespace glimmer {

Json jsonNumber(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}

Json jsonNumber(double v, int digits) {
    if (!std::isfinite(v)) return jsonNumber(v);
    // Through the decimal text: the double nearest to it, which nlohmann
    // writes back as that same short text. fmt: no locale's decimal comma.
    const std::string text = fmt::format("{:.{}g}", v, digits);
    double rounded = v;
    parseDouble(text.data(), text.data() + text.size(), rounded);
    return rounded;
}

bool numberFromJson(const Json& v, double& out) {
    if (v.is_number()) {
        out = v.get<double>();
        return true;
    }
    if (!v.is_string()) return false;
    const std::string& s = v.get_ref<const std::string&>();
    if (s == "nan") out = NAN;
    else if (s == "inf") out = INFINITY;
    else if (s == "-inf") out = -INFINITY;
    else return false;
    return true;
}

// error_handler_t::replace: invalid UTF-8 becomes U+FFFD instead of a
// type_error thrown out of the program (nlohmann's default).
std::string jsonLine(const Json& v) { return v.dump(-1, ' ', false, Json::error_handler_t::replace); }

std::string jsonDocument(const Json& v) { return v.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"; }

bool parseJson(const std::string& text, Json& out, std::string& error) {
    try {
        out = Json::parse(text);
        return true;
    } catch (const Json::exception& e) {
        // "[json.exception.parse_error.101] parse error at line 1, column 21: syntax error ..."
        // without the tag, and without the line when there is only one.
        std::string why = e.what();
        if (why.rfind("[json.exception.", 0) == 0 && why.find("] ") != std::string::npos)
            why.erase(0, why.find("] ") + 2);
        if (why.rfind("parse error ", 0) == 0) why.erase(0, 12);
        if (text.find('\n') == std::string::npos && why.rfind("at line 1, column ", 0) == 0)
            why = "at column " + why.substr(18);
        error = why;
        return false;
    }
}

}  // namespace glimmer
