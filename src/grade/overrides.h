// The teacher's word over the machine's: an overrides file, a CSV the
// teacher keeps beside the grading (`--overrides FILE`), one line per
// student whose grade or comment the teacher sets by hand:
//
//   student,score,comment
//   alice,85,"the blur is right; the threshold was asked for in luma"
//   bob,,see me about the edges
//
// A score (a whole number 0..100) replaces the computed one in the report
// and the CSV, which keep the computed one beside it; an empty score keeps
// it. The comment goes to the report, the CSV and the student's feedback
// page. The records (grades.jsonl) stay the machine's: the file is applied
// every time a report is written, so it can be edited and applied again
// (batch-merge takes it too). Pure text in, values out; no files here.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grade/grade_row.h"

namespace glimmer {

struct Override {
    std::optional<int> score;
    std::string comment;
};

// Parses the file's text (`file` names it in messages). False, with one
// compiler-style message in `error` ("FILE:LINE: error: ..."), for a
// header other than "student,score,comment", a line with another number of
// cells, a score that is not a whole number 0..100, a student named twice,
// or more than 100,000 lines.
bool parseOverrides(const std::string& text, const std::string& file, std::map<std::string, Override>& out,
                    std::string& error);

// Applies them to `rows` (GradeRow::computedScore keeps the machine's);
// returns the students named that no row has, for a warning.
std::vector<std::string> applyOverrides(std::vector<GradeRow>& rows, const std::map<std::string, Override>& overrides);

}  // namespace glimmer
