#include "util/json_string.h"

#include <fmt/format.h>

namespace glimmer {

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        case '\r': out += "\\r"; break;
        default:
            if (c < 0x20) out += fmt::format("\\u{:04x}", c);
            else out += char(c);
        }
    }
    return out + "\"";
}

}  // namespace glimmer
