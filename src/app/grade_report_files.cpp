// Writing a grading run's files for people: report.html and grades.csv
// from rows (pictures read back and inlined as thumbnails), each written
// whole through a temporary file and a rename, so a reader or a kill never
// sees half a page. Shared by batch --reference and batch-merge.
#include <filesystem>
#include <fstream>

#include "app/grade_batch.h"
#include "util/write_file.h"
#include "grade/grading.h"
#include "image/image.h"
#include "image/png_stream.h"

namespace glimmer {
namespace fs = std::filesystem;
namespace {

std::string dataUrl(const Image& picture) {
    return picture.empty() ? "" : "data:image/png;base64," + base64(encodePng(thumbnail(picture, 96), 6));
}

RowPictures rowPictures(const GradeRow& row, const fs::path& dir) {
    RowPictures p;
    Image student, solution;
    std::string why;
    const bool haveStudent = !row.picture.empty() && loadImage((dir / row.picture).string(), student, why);
    const bool haveSolution = !row.solution.empty() && loadImage((dir / row.solution).string(), solution, why);
    if (haveStudent) p.student = dataUrl(student);
    if (haveSolution) p.solution = dataUrl(solution);
    if (haveStudent && haveSolution) p.difference = dataUrl(differencePicture(student, solution));
    return p;
}

}  // namespace

bool writeWhole(const fs::path& path, const std::string& text) {
    std::string error;
    return writeBytesReplacing(path.string(), text.data(), text.size(), error);
}

void writeReport(const fs::path& dir, const ReportHeader& header, std::vector<GradeRow> rows,
                 std::map<std::string, std::string>& rowHtml, const fs::path& picturesDir) {
    sortForReview(rows);
    std::vector<std::string> html;
    for (const auto& r : rows) {
        auto it = rowHtml.find(r.student);
        if (it == rowHtml.end()) it = rowHtml.emplace(r.student, reportRowHtml(r, rowPictures(r, picturesDir))).first;
        html.push_back(it->second);
    }
    writeWhole(dir / "report.html", reportHtml(header, rows, html));
    writeWhole(dir / "grades.csv", gradesCsv(rows));
}

}  // namespace glimmer
