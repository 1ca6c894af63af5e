// What a teacher reads after a grading run: one self-contained HTML page
// (pictures inline as data URLs, so it can be mailed or archived as one
// file) and a CSV a gradebook imports. Pure text from rows; no GL.
#pragma once
#include <string>
#include <vector>

#include "grade/grade_row.h"

namespace glimmer {

// What the page says above the rows: how the grading was done.
struct ReportHeader {
    std::string solution;                 // the reference script
    std::vector<std::string> settings;    // their labels
    std::string thresholds;               // in words
    bool sandbox = true;
    // A hash of the solution's script and every file it reads: --resume
    // compares the solution's content, not only its path (issue 37: a
    // changed solution under the same name kept stale grades). "" before.
    std::string solutionContent;
    int expected = 0;                     // submissions in the class (the page says how many are still missing)
};

// The pictures of one row, as data URLs ("" where there is none), and
// where a click goes: the full-size PNGs and the student's feedback page,
// relative to the report ("" where there is none).
struct RowPictures {
    std::string student, solution, difference;
    std::string studentHref, solutionHref, feedbackHref;
};

// A student's feedback page (feedback/NAME.html beside the report), to hand
// back: the verdict and score (the teacher's, where set), the teacher's
// comment, the notes and the compiler's messages, and at every setting the
// student's picture beside the solution's and their difference, full size
// (data URLs: the page is one file).
struct SettingPictures {
    std::string label;
    std::string student, solution, difference;  // data URLs, "" where there is none
};
std::string feedbackHtml(const GradeRow& row, const std::string& solutionName, const std::vector<SettingPictures>& settings);

// `path` for an href: bytes outside RFC 3986's unreserved set and '/'
// percent-encoded (a student's name may hold '#', '?', '%' or letters beyond ASCII).
std::string hrefOf(const std::string& path);

// The ones needing a person first: error, wrong, look, pass; within each,
// the lowest score first, then by name.
void sortForReview(std::vector<GradeRow>& rows);

// One row of the page's table (cached by the caller: a page is rewritten as
// results arrive, and a row's pictures are encoded only once).
std::string reportRowHtml(const GradeRow& row, const RowPictures& pictures);
// The whole page around rows made by reportRowHtml, in the order given.
std::string reportHtml(const ReportHeader& header, const std::vector<GradeRow>& rows,
                       const std::vector<std::string>& rowHtml);

// student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,
// submission,computed_score,comment: one line per row in name order, quoted
// where needed; a cell that a spreadsheet would run as a formula (= + - @
// first, or a tab or CR) starts with a quote. score is the teacher's where
// an overrides file sets one, computed_score then the machine's.
std::string gradesCsv(std::vector<GradeRow> rows);

// Text for HTML: & < > " ' escaped.
std::string htmlEscape(const std::string& text);

}  // namespace glimmer
