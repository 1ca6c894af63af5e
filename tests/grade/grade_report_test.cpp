// The report's order, its CSV and HTML text, and the record file that
// --resume and batch-merge read back.
#include <gtest/gtest.h>

#include <cmath>

#include "grade/grade_report.h"
#include "grade/grade_row.h"

namespace glimmer {
namespace {

GradeRow row(const std::string& who, const std::string& verdict, int score) {
    GradeRow r;
    r.student = who;
    r.verdict = verdict;
    r.score = score;
    return r;
}

TEST(GradeReport, TheOnesNeedingALookComeFirst) {
    std::vector<GradeRow> rows{row("amy", "pass", 100), row("ben", "look", 90), row("cy", "error", 0),
                               row("di", "wrong", 40), row("ed", "wrong", 10), row("al", "pass", 99)};
    sortForReview(rows);
    std::string order;
    for (const auto& r : rows) order += r.student + " ";
    EXPECT_EQ(order, "cy ed di ben al amy ");
}

TEST(GradeReport, CsvIsInNameOrderQuotedAndFormulaSafe) {
    GradeRow a = row("=HYPERLINK(\"x\")", "wrong", 40);
    a.ssim = 0.4;
    a.psnr = 12.345;
    a.seconds = 0.5;
    a.notes = "SSIM 0.400, PSNR 12.3 dB at the worst setting";
    GradeRow b = row("bob", "error", 0);
    b.diagnostics = "class/bob/x.glib:3:1: error: Ortho takes 4 numbers, got 3\n  Ortho -1 1 -1\n  ^\n";
    GradeRow c = row("amy", "pass", 100);
    c.ssim = 1;
    c.psnr = INFINITY;
    EXPECT_EQ(gradesCsv({a, b, c}),
              "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic\n"
              "\"'=HYPERLINK(\"\"x\"\")\",40,wrong,0.4000,12.35,0.50,\"SSIM 0.400, PSNR 12.3 dB at the worst setting\",\n"
              "amy,100,pass,1.0000,inf,0.00,,\n"
              "bob,0,error,,,0.00,,\"class/bob/x.glib:3:1: error: Ortho takes 4 numbers, got 3\"\n");
}

TEST(GradeReport, RecordsReadBackExactly) {
    GradeRow r = row("zoë \"z\"", "look", 91);
    r.submission = "class/zoe.zip";
    r.script = "out/unpacked/zoe/a b.glib";
    r.ssim = 0.912345;
    r.psnr = INFINITY;
    r.worstSetting = "uA=1";
    r.bySetting = "defaults 1.000 · uA=1 0.912";
    r.notes = "lacks the solution's uniform uB";
    r.diagnostics = "x.glib:1:1: warning: tab\there\n  line\n";
    r.seconds = 1.25;
    r.picture = "pictures/zoe-2.png";
    r.solution = "pictures/solution-2.png";
    std::string line = gradeRecord(r);
    EXPECT_EQ(line.find('\n'), std::string::npos);
    GradeRow back;
    std::string error;
    ASSERT_TRUE(parseGradeRecord(line, back, error)) << error;
    EXPECT_EQ(gradeRecord(back), line);
    EXPECT_TRUE(std::isinf(back.psnr));
    EXPECT_EQ(back.diagnostics, r.diagnostics);
    EXPECT_FALSE(parseGradeRecord(line.substr(0, line.size() / 2), back, error));
    std::string huge = line;
    huge.replace(huge.find("\"score\": 91"), 11, "\"score\": 1e300");
    EXPECT_FALSE(parseGradeRecord(huge, back, error));
    EXPECT_EQ(error, "score '1e300' is not a whole number from 0 to 100");
    EXPECT_FALSE(parseGradeRecord("{\"student\": \"x\"}", back, error));
    EXPECT_EQ(error, "no \"submission\"");
}

TEST(GradeReport, TheHtmlEscapesWhatStudentsWrote) {
    GradeRow r = row("<script>alert(1)</script>", "error", 0);
    r.diagnostics = "a.glib:1:1: error: '<' is never closed\n";
    std::string html = reportRowHtml(r, {});
    EXPECT_EQ(html.find("<script>"), std::string::npos);
    EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
    EXPECT_NE(html.find("<pre>a.glib:1:1: error: &#39;&lt;&#39; is never closed\n</pre>"), std::string::npos);
    EXPECT_NE(html.find("<div class=none>no student</div>"), std::string::npos);
    ReportHeader h;
    h.solution = "sol.glib";
    h.settings = {"defaults", "uA=1"};
    h.thresholds = "pass: SSIM >= 0.95 and PSNR >= 30 dB";
    h.expected = 3;
    std::string page = reportHtml(h, {r}, {html});
    EXPECT_NE(page.find("1 submissions of 3 (the rest still running) · compared at 2 settings: defaults · uA=1"),
              std::string::npos);
    EXPECT_NE(page.find("<span class=error>1 error</span>"), std::string::npos);
    // The glance strip links to the row.
    EXPECT_NE(page.find("<a class=error href=\"#s-&lt;script&gt;alert(1)&lt;/script&gt;\">&lt;script&gt;alert(1)&lt;/script&gt; 0</a>"),
              std::string::npos);
    EXPECT_NE(html.find("id=\"s-&lt;script&gt;alert(1)&lt;/script&gt;\""), std::string::npos);
}

}  // namespace
}  // namespace glimmer
