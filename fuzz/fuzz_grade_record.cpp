// libFuzzer: what `glimmer batch --resume` and `batch-merge` read back from
// a grading folder (grades.jsonl, grading.txt), which a shard on another
// machine, a kill mid-write or a person may have left in any state; and the
// zip entry-name check. Whatever parses must write back to the same record,
// and the report writers must take it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "grade/grade_merge.h"
#include "grade/grade_report.h"
#include "grade/grade_row.h"
#include "grade/safe_unzip.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glimmer;
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<GradeRow> rows;
    std::string error;
    if (parseRecords(text, "fuzz.jsonl", rows, error)) {
        for (const auto& r : rows) {
            GradeRow back;
            if (!parseGradeRecord(gradeRecord(r), back, error) || gradeRecord(back) != gradeRecord(r)) __builtin_trap();
        }
        sortForReview(rows);
        std::vector<std::string> html;
        for (const auto& r : rows) html.push_back(reportRowHtml(r, {}));
        ReportHeader header;
        if (reportHtml(header, rows, html).empty() || gradesCsv(rows).empty()) __builtin_trap();
    }
    ReportHeader header;
    std::vector<std::string> students;
    if (parseRunHeader(text, header, students, error)) {
        ReportHeader again;
        std::vector<std::string> againStudents;
        if (!parseRunHeader(runHeaderText(header, students), again, againStudents, error)) __builtin_trap();
    }
    unsafeEntryName(text);
    return 0;
}
