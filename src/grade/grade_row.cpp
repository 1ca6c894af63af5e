#include "grade/grade_row.h"

#include <cmath>
#include <map>

#include <fmt/format.h>

#include "util/json.h"

namespace glimmer {
namespace {

// What the record's keys hold besides "score" (a whole number): text, or a
// number (util/json.h: "nan", "inf" and "-inf" for the non-finite ones).
const char* const kStringKeys[] = {"student", "submission", "script", "verdict", "worst_setting", "by_setting",
                                   "notes", "diagnostics", "picture", "solution"};
const char* const kNumberKeys[] = {"ssim", "psnr", "seconds"};

}  // namespace

// Numbers to 6 significant digits (all the report shows, and all a record
// ever held); a PSNR of +Inf (a picture equal to the solution's) is "inf"
// (util/json.h).
std::string gradeRecord(const GradeRow& r) {
    Json j;
    j["student"] = r.student;
    j["submission"] = r.submission;
    j["script"] = r.script;
    j["verdict"] = r.verdict;
    j["score"] = r.score;
    j["ssim"] = jsonNumber(r.ssim, 6);
    j["psnr"] = jsonNumber(r.psnr, 6);
    j["worst_setting"] = r.worstSetting;
    j["by_setting"] = r.bySetting;
    j["notes"] = r.notes;
    j["diagnostics"] = r.diagnostics;
    j["seconds"] = jsonNumber(r.seconds, 6);
    j["picture"] = r.picture;
    j["solution"] = r.solution;
    return jsonLine(j);
}

bool parseGradeRecord(const std::string& line, GradeRow& r, std::string& error) {
    Json j;
    if (!parseJson(line, j, error)) return false;
    if (!j.is_object()) return error = "not a JSON object", false;
    for (const char* key : {"student", "submission", "script", "verdict", "score", "ssim", "psnr", "worst_setting",
                            "by_setting", "notes", "diagnostics", "seconds", "picture", "solution"})
        if (!j.contains(key)) return error = fmt::format("no \"{}\"", key), false;
    for (const char* key : kStringKeys)
        if (!j.at(key).is_string()) return error = fmt::format("\"{}\" is not a string", key), false;
    std::map<std::string, double> number;
    for (const char* key : kNumberKeys)
        if (!numberFromJson(j.at(key), number[key]))
            return error = fmt::format("\"{}\": {} is not a number", key, jsonLine(j.at(key))), false;
    const Json& score = j.at("score");
    if (!score.is_number() || !(score.get<double>() >= 0 && score.get<double>() <= 100) ||
        score.get<double>() != std::floor(score.get<double>()))  // never cast out of range
        return error = fmt::format("score '{}' is not a whole number from 0 to 100", jsonLine(score)), false;
    auto text = [&](const char* key) { return j.at(key).get<std::string>(); };
    r.student = text("student");
    r.submission = text("submission");
    r.script = text("script");
    r.verdict = text("verdict");
    r.score = int(score.get<double>());
    r.ssim = number["ssim"];
    r.psnr = number["psnr"];
    r.worstSetting = text("worst_setting");
    r.bySetting = text("by_setting");
    r.notes = text("notes");
    r.diagnostics = text("diagnostics");
    r.seconds = number["seconds"];
    r.picture = text("picture");
    r.solution = text("solution");
    if (r.verdict != "pass" && r.verdict != "look" && r.verdict != "wrong" && r.verdict != "error")
        return error = fmt::format("verdict '{}' is not pass, look, wrong or error", r.verdict), false;
    return true;
}

}  // namespace glimmer
