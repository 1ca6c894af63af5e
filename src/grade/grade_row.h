// One student's line in a grading run: what the report, the CSV and the
// record file (for --resume and batch-merge) all hold. Plain values.
#pragma once
#include <string>
#include <vector>

namespace glimmer {

struct GradeRow {
    std::string student;      // the folder's or zip's name
    std::string submission;   // the path it came from
    std::string script;       // the script graded ("" when none was found)
    std::string verdict;      // pass, look, wrong, error (grade/grading.h)
    int score = 0;            // 0..100
    double ssim = 0, psnr = 0;  // at the worst setting
    std::string worstSetting;   // its label ("uX=1")
    std::string bySetting;      // SSIM at each setting, in words ("defaults 1.000 · uX=1 0.412")
    std::string notes;          // the verdict's why
    std::string diagnostics;    // as printed: file:line:col: error: ..., the source line, a caret
    double seconds = 0;         // render time of every setting
    std::string picture;        // the student's PNG at the worst setting ("" when none)
    std::string solution;       // the solution's PNG at that setting
    // The teacher's, from an overrides file (grade/overrides.h), applied when
    // a report is written; never in the records.
    int computedScore = -1;     // the machine's score when the teacher set another; -1: not overridden
    std::string comment;
};

// One JSON object on one line (util/json.h's rules: UTF-8, "inf" for an
// infinite PSNR); parseGradeRecord reads back exactly what gradeRecord
// wrote (the fields above), and refuses anything else with `error`.
std::string gradeRecord(const GradeRow& row);
bool parseGradeRecord(const std::string& line, GradeRow& row, std::string& error);

}  // namespace glimmer
