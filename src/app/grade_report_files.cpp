// Writing a grading run's files for people: report.html and grades.csv
// from rows (pictures read back and inlined as thumbnails), each written
// whole through a temporary file and a rename, so a reader or a kill never
// sees half a page. Shared by batch --reference and batch-merge.
#include <cctype>
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

// A picture as a PNG data URL ("" for none), at most `maxSide` on its
// longer side (the report's thumbnails; 0: full size, the feedback pages).
std::string dataUrl(const Image& picture, int maxSide = 0) {
    if (picture.empty()) return "";
    return "data:image/png;base64," + base64(encodePng(maxSide > 0 ? thumbnail(picture, maxSide) : picture, 6));
}

// "pictures/alice-3.png" -> "pictures/alice-": the setting's number is
// the last thing before ".png" (app/grade_batch.cpp names them so).
std::string settingPrefix(const std::string& picture) {
    if (picture.size() < 5 || picture.compare(picture.size() - 4, 4, ".png") != 0) return "";
    size_t end = picture.size() - 4, start = end;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(picture[start - 1]))) --start;
    return start < end && start > 0 && picture[start - 1] == '-' ? picture.substr(0, start) : "";
}


// The student's feedback page: every setting's pictures, full size.
void writeFeedback(const fs::path& dir, const ReportHeader& header, const GradeRow& row, const fs::path& picturesDir) {
    std::vector<SettingPictures> settings;
    const std::string mine = settingPrefix(row.picture), theirs = settingPrefix(row.solution);
    for (size_t k = 0; k < header.settings.size() && !mine.empty() && !theirs.empty(); ++k) {
        SettingPictures s;
        s.label = header.settings[k];
        Image student, solution;
        std::string why;
        const bool a = loadImage((picturesDir / (mine + std::to_string(k) + ".png")).string(), student, why);
        const bool b = loadImage((picturesDir / (theirs + std::to_string(k) + ".png")).string(), solution, why);
        if (a) s.student = dataUrl(student);
        if (b) s.solution = dataUrl(solution);
        if (a && b) s.difference = dataUrl(differencePicture(student, solution));
        settings.push_back(s);
    }
    std::error_code ec;
    fs::create_directories(dir / "feedback", ec);
    // The solution by its name only: the page goes to a student, the teacher's folders stay the teacher's.
    writeWhole(dir / "feedback" / (row.student + ".html"),
               feedbackHtml(row, fs::path(header.solution).filename().string(), settings));
}

RowPictures rowPictures(const GradeRow& row, const fs::path& dir) {
    RowPictures p;
    p.studentHref = row.picture;
    p.solutionHref = row.solution;
    p.feedbackHref = "feedback/" + row.student + ".html";
    Image student, solution;
    std::string why;
    const bool haveStudent = !row.picture.empty() && loadImage((dir / row.picture).string(), student, why);
    const bool haveSolution = !row.solution.empty() && loadImage((dir / row.solution).string(), solution, why);
    if (haveStudent) p.student = dataUrl(student, 96);
    if (haveSolution) p.solution = dataUrl(solution, 96);
    if (haveStudent && haveSolution) p.difference = dataUrl(differencePicture(student, solution), 96);
    return p;
}

}  // namespace

bool writeWhole(const fs::path& path, const std::string& text) {
    std::string error;
    return writeBytesReplacing(path.string(), text.data(), text.size(), error);
}

bool feedbackStillRight(const fs::path& dir, const GradeRow& row, const std::map<std::string, Override>& overrides) {
    if (overrides.count(row.student)) return false;
    std::ifstream page(dir / "feedback" / (row.student + ".html"), std::ios::binary);
    if (!page) return false;
    // The override's lines come right after the heading (grade_report.cpp's feedbackHtml): the
    // page's first 16 KiB hold them when they are there.
    std::string head(16 * 1024, '\0');
    page.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(page.gcount()));
    return head.find("(set by your teacher; computed") == std::string::npos &&
           head.find("<p class=comment>Your teacher: ") == std::string::npos;
}

void writeReport(const fs::path& dir, const ReportHeader& header, std::vector<GradeRow> rows,
                 std::map<std::string, std::string>& rowHtml, const fs::path& picturesDir,
                 const std::map<std::string, Override>& overrides, const std::set<std::string>& feedbackKept) {
    applyOverrides(rows, overrides);
    sortForReview(rows);
    std::vector<std::string> html;
    for (const auto& r : rows) {
        auto it = rowHtml.find(r.student);
        if (it == rowHtml.end()) {  // a row's pictures and its feedback page are made once
            it = rowHtml.emplace(r.student, reportRowHtml(r, rowPictures(r, picturesDir))).first;
            if (!feedbackKept.count(r.student)) writeFeedback(dir, header, r, picturesDir);
        }
        html.push_back(it->second);
    }
    writeWhole(dir / "report.html", reportHtml(header, rows, html));
    writeWhole(dir / "grades.csv", gradesCsv(rows));
}

}  // namespace glimmer
