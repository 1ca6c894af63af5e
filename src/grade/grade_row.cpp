#include "grade/grade_row.h"

#include <cmath>
#include <cstdlib>
#include <map>

#include <fmt/format.h>

#include "util/json_string.h"
#include "util/numbers.h"

namespace glimmer {
namespace {

// A flat object of string and number values: all a record holds.
bool parseFlat(const std::string& s, std::map<std::string, std::string>& out, std::string& error) {
    size_t i = 0;
    auto ws = [&] { while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i; };
    auto str = [&](std::string& v) {
        if (i >= s.size() || s[i] != '"') return false;
        ++i;
        while (i < s.size() && s[i] != '"') {
            if (s[i] == '\\') {
                if (++i >= s.size()) return false;
                switch (s[i]) {
                case 'n': v += '\n'; break;
                case 't': v += '\t'; break;
                case 'r': v += '\r'; break;
                case 'u':
                    if (i + 4 >= s.size()) return false;
                    v += char(std::strtol(s.substr(i + 1, 4).c_str(), nullptr, 16));
                    i += 4;
                    break;
                default: v += s[i];
                }
            } else {
                v += s[i];
            }
            ++i;
        }
        if (i >= s.size()) return false;
        ++i;
        return true;
    };
    ws();
    if (i >= s.size() || s[i++] != '{') return error = "not a JSON object", false;
    for (;;) {
        ws();
        if (i < s.size() && s[i] == '}') return true;
        std::string key, value;
        if (!str(key)) return error = "expected a quoted key", false;
        ws();
        if (i >= s.size() || s[i++] != ':') return error = "expected ':' after \"" + key + "\"", false;
        ws();
        if (i < s.size() && s[i] == '"') {
            if (!str(value)) return error = "unterminated string for \"" + key + "\"", false;
        } else {
            while (i < s.size() && s[i] != ',' && s[i] != '}' && s[i] != ' ') value += s[i++];
            if (value.empty()) return error = "no value for \"" + key + "\"", false;
        }
        out[key] = value;
        ws();
        if (i < s.size() && s[i] == ',') ++i;
        else if (i < s.size() && s[i] == '}') return true;
        else return error = "expected ',' or '}'", false;
    }
}

std::string number(double v) {
    if (std::isinf(v)) return v > 0 ? "\"inf\"" : "\"-inf\"";
    if (std::isnan(v)) return "\"nan\"";
    return fmt::format("{:.6g}", v);
}

}  // namespace

std::string gradeRecord(const GradeRow& r) {
    return fmt::format("{{\"student\": {}, \"submission\": {}, \"script\": {}, \"verdict\": {}, \"score\": {}, "
                       "\"ssim\": {}, \"psnr\": {}, \"worst_setting\": {}, \"by_setting\": {}, \"notes\": {}, \"diagnostics\": {}, "
                       "\"seconds\": {}, \"picture\": {}, \"solution\": {}}}",
                       jsonString(r.student), jsonString(r.submission), jsonString(r.script), jsonString(r.verdict), r.score,
                       number(r.ssim), number(r.psnr), jsonString(r.worstSetting), jsonString(r.bySetting), jsonString(r.notes),
                       jsonString(r.diagnostics), number(r.seconds), jsonString(r.picture), jsonString(r.solution));
}

bool parseGradeRecord(const std::string& line, GradeRow& r, std::string& error) {
    std::map<std::string, std::string> f;
    if (!parseFlat(line, f, error)) return false;
    for (const char* key : {"student", "submission", "script", "verdict", "score", "ssim", "psnr", "worst_setting",
                            "by_setting", "notes", "diagnostics", "seconds", "picture", "solution"})
        if (!f.count(key)) return error = fmt::format("no \"{}\"", key), false;
    auto num = [](const std::string& s) {  // from_chars: no locale's decimal comma; reads inf and nan
        double v = 0;
        parseDouble(s.data(), s.data() + s.size(), v);
        return v;
    };
    r.student = f["student"];
    r.submission = f["submission"];
    r.script = f["script"];
    r.verdict = f["verdict"];
    const double score = num(f["score"]);
    if (!(score >= 0 && score <= 100) || score != std::floor(score))  // NaN fails too; never cast out of range
        return error = fmt::format("score '{}' is not a whole number from 0 to 100", f["score"]), false;
    r.score = int(score);
    r.ssim = num(f["ssim"]);
    r.psnr = num(f["psnr"]);
    r.worstSetting = f["worst_setting"];
    r.bySetting = f["by_setting"];
    r.notes = f["notes"];
    r.diagnostics = f["diagnostics"];
    r.seconds = num(f["seconds"]);
    r.picture = f["picture"];
    r.solution = f["solution"];
    if (r.verdict != "pass" && r.verdict != "look" && r.verdict != "wrong" && r.verdict != "error")
        return error = fmt::format("verdict '{}' is not pass, look, wrong or error", r.verdict), false;
    return true;
}

}  // namespace glimmer
