// The folder a grading run leaves, read back: by --resume (what is already
// graded) and by `glimmer batch-merge` (the shards of a job array joined
// into one report). Pure text in, rows out; no GL.
#pragma once
#include <string>
#include <vector>

#include "grade/grade_report.h"
#include "grade/grade_row.h"

namespace glimmer {

// grading.txt: how the run grades, and the whole class in list order (the
// same in every shard), so a merge can tell what is missing.
//   solution: sol.glib / setting: uX=1 (repeated) / thresholds: ... /
//   sandbox: on|off / student: alice (repeated)
std::string runHeaderText(const ReportHeader& header, const std::vector<std::string>& students);
bool parseRunHeader(const std::string& text, ReportHeader& header, std::vector<std::string>& students, std::string& error);

// grades.jsonl: one record a line (grade/grade_row.h). A last line cut off
// by a kill is dropped (it is graded again); any other bad line is an error
// naming `file` and the line number. A student graded twice keeps the
// later record.
bool parseRecords(const std::string& text, const std::string& file, std::vector<GradeRow>& rows, std::string& error);

// The shards' rows joined: every student of `students` exactly once. False,
// with one line per problem in `errors` ("alice: graded by 2 shards",
// "bob: in no shard's results", "zed: not in the class list"), when not.
bool mergeShardRows(const std::vector<std::vector<GradeRow>>& shards, const std::vector<std::string>& students,
                    std::vector<GradeRow>& merged, std::vector<std::string>& errors);

}  // namespace glimmer
