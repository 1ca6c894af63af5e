#include "grade/overrides.h"

#include <set>

#include <fmt/format.h>

namespace glimmer {
namespace {

constexpr size_t kMaxLines = 100000;

// One CSV record (RFC 4180: quoted cells, "" for a quote, line breaks
// inside quotes) from `at`; false when a quote never closes.
bool readRecord(const std::string& text, size_t& at, std::vector<std::string>& cells, int& lines) {
    cells.assign(1, "");
    bool quoted = false;
    while (at < text.size()) {
        const char c = text[at++];
        if (quoted) {
            if (c == '"' && at < text.size() && text[at] == '"') cells.back() += '"', ++at;
            else if (c == '"') quoted = false;
            else {
                if (c == '\n') ++lines;
                cells.back() += c;
            }
        } else if (c == '"' && cells.back().empty()) {
            quoted = true;
        } else if (c == ',') {
            cells.emplace_back();
        } else if (c == '\n') {
            ++lines;
            break;
        } else if (c != '\r') {
            cells.back() += c;
        }
    }
    return !quoted;
}

}  // namespace

bool parseOverrides(const std::string& text, const std::string& file, std::map<std::string, Override>& out,
                    std::string& error) {
    out.clear();
    size_t at = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // a spreadsheet's BOM
    int line = 1;
    std::vector<std::string> cells;
    auto fail = [&](int where, const std::string& why) {
        error = fmt::format("{}:{}: error: {}", file, where, why);
        return false;
    };
    int start = line;
    if (!readRecord(text, at, cells, line) || cells != std::vector<std::string>{"student", "score", "comment"})
        return fail(start, "the first line must be 'student,score,comment'");
    for (size_t n = 0; at < text.size(); ++n) {
        if (n >= kMaxLines) return fail(line, fmt::format("more than {} lines", kMaxLines));
        start = line;
        if (!readRecord(text, at, cells, line)) return fail(start, "a quote that is never closed");
        if (cells.size() == 1 && cells[0].empty()) continue;  // a blank line
        if (cells.size() != 3) return fail(start, fmt::format("{} cells; a line is student,score,comment", cells.size()));
        Override o;
        if (!cells[1].empty()) {
            int score = 0;
            bool digits = cells[1].size() <= 3;
            for (char c : cells[1]) digits = digits && c >= '0' && c <= '9', score = score * 10 + (c - '0');
            if (!digits || score > 100)
                return fail(start, fmt::format("score '{}' is not a whole number from 0 to 100", cells[1].substr(0, 40)));
            o.score = score;
        }
        o.comment = cells[2];
        if (cells[0].empty()) return fail(start, "a line without a student");
        if (!out.emplace(cells[0], o).second)
            return fail(start, fmt::format("'{}' is named twice", cells[0].substr(0, 80)));
    }
    return true;
}

std::vector<std::string> applyOverrides(std::vector<GradeRow>& rows, const std::map<std::string, Override>& overrides) {
    std::set<std::string> used;
    for (auto& r : rows) {
        auto it = overrides.find(r.student);
        if (it == overrides.end()) continue;
        used.insert(r.student);
        if (it->second.score) {
            r.computedScore = r.score;
            r.score = *it->second.score;
        }
        r.comment = it->second.comment;
    }
    std::vector<std::string> unknown;
    for (const auto& [name, o] : overrides)
        if (!used.count(name)) unknown.push_back(name);
    return unknown;
}

}  // namespace glimmer
