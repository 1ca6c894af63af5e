#include "serve/roster.h"

#include <fmt/format.h>
#include <set>

namespace glimmer {
namespace {

constexpr std::size_t kMaxStudents = 2000;
constexpr std::size_t kMaxName = 60;

// The first field of a CSV line: up to the first comma, or a quoted field
// with "" for a quote inside.
std::string firstField(const std::string& line) {
    if (line.empty() || line[0] != '"') return line.substr(0, line.find(','));
    std::string out;
    for (std::size_t i = 1; i < line.size(); ++i) {
        if (line[i] != '"') out += line[i];
        else if (i + 1 < line.size() && line[i + 1] == '"') out += '"', ++i;
        else break;
    }
    return out;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.pop_back();
    std::size_t start = 0;
    while (start < s.size() && (s[start] == ' ' || s[start] == '\t')) ++start;
    return s.substr(start);
}

}  // namespace

bool parseRoster(const std::string& text, const std::string& file, std::vector<std::string>& names, std::string& error) {
    std::set<std::string> seen;
    std::size_t at = 0;
    int lineNo = 0;
    while (at < text.size()) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(at, end - at);
        at = end + 1;
        ++lineNo;
        const std::string name = trimmed(firstField(trimmed(line)));
        if (trimmed(line).empty()) continue;
        if (lineNo == 1 && (name == "name" || name == "Name" || name == "NAME")) continue;
        auto fail = [&](const std::string& why) {
            error = fmt::format("{}:{}:1: error: {}\n{}\n^", file, lineNo, why, line);
            return false;
        };
        if (name.empty()) return fail("no name before the first comma");
        if (name.size() > kMaxName) return fail(fmt::format("a name is at most {} bytes", kMaxName));
        for (unsigned char c : name)
            if (c < 32 || c == 127) return fail("a control character in the name");
        if (!seen.insert(name).second) return fail(fmt::format("'{}' comes twice: each student once", name));
        if (names.size() >= kMaxStudents) return fail(fmt::format("more than {} students", kMaxStudents));
        names.push_back(name);
    }
    if (names.empty()) {
        error = fmt::format("{}: error: no student in it", file);
        return false;
    }
    return true;
}

}  // namespace glimmer
