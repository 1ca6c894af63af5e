#include "grade/grade_merge.h"

#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

namespace glimmer {

std::string runHeaderText(const ReportHeader& h, const std::vector<std::string>& students) {
    std::string out = "solution: " + h.solution + "\n";
    for (const auto& s : h.settings) out += "setting: " + s + "\n";
    out += "thresholds: " + h.thresholds + "\n";
    out += std::string("sandbox: ") + (h.sandbox ? "on" : "off") + "\n";
    if (!h.solutionContent.empty()) out += "solution-content: " + h.solutionContent + "\n";
    for (const auto& s : students) out += "student: " + s + "\n";
    return out;
}

bool parseRunHeader(const std::string& text, ReportHeader& h, std::vector<std::string>& students, std::string& error) {
    h = ReportHeader{};
    students.clear();
    std::istringstream in(text);
    int n = 0;
    bool solution = false;
    for (std::string line; std::getline(in, line);) {
        ++n;
        auto colon = line.find(": ");
        if (colon == std::string::npos) return error = fmt::format("line {}: not 'key: value'", n), false;
        const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
        if (key == "solution") h.solution = value, solution = true;
        else if (key == "setting") h.settings.push_back(value);
        else if (key == "thresholds") h.thresholds = value;
        else if (key == "sandbox") h.sandbox = value == "on";
        else if (key == "solution-content") h.solutionContent = value;
        else if (key == "student") students.push_back(value);
        else return error = fmt::format("line {}: unknown key '{}'", n, key), false;
    }
    if (!solution) return error = "no 'solution:' line", false;
    h.expected = int(students.size());
    return true;
}

bool parseRecords(const std::string& text, const std::string& file, std::vector<GradeRow>& rows, std::string& error) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    const bool cutOff = !text.empty() && text.back() != '\n';
    std::map<std::string, size_t> at;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].empty()) continue;
        GradeRow r;
        std::string why;
        if (!parseGradeRecord(lines[i], r, why)) {
            if (cutOff && i + 1 == lines.size()) break;  // killed while writing it
            error = fmt::format("{}:{}: error: {}", file, i + 1, why);
            return false;
        }
        auto it = at.find(r.student);
        if (it != at.end()) rows[it->second] = r;
        else at[r.student] = rows.size(), rows.push_back(r);
    }
    return true;
}

bool mergeShardRows(const std::vector<std::vector<GradeRow>>& shards, const std::vector<std::string>& students,
                    std::vector<GradeRow>& merged, std::vector<std::string>& errors) {
    std::map<std::string, int> times;
    std::set<std::string> known(students.begin(), students.end());
    merged.clear();
    for (const auto& shard : shards)
        for (const auto& r : shard) {
            if (++times[r.student] == 1) merged.push_back(r);
        }
    for (const auto& s : students) {
        if (times[s] == 0) errors.push_back(s + ": in no shard's results");
        else if (times[s] > 1) errors.push_back(fmt::format("{}: graded by {} shards", s, times[s]));
    }
    for (const auto& [name, n] : times)
        if (n > 0 && !known.count(name)) errors.push_back(name + ": not in the class list");
    return errors.empty();
}

}  // namespace glimmer
