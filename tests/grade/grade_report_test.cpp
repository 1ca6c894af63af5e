// The report's order, its CSV and HTML text, and the record file that
// --resume and batch-merge read back.
#include <gtest/gtest.h>

#include <cmath>

#include "grade/grade_report.h"
#include "grade/overrides.h"
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
              "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,computed_score,comment\n"
              "\"'=HYPERLINK(\"\"x\"\")\",40,wrong,0.4000,12.35,0.50,\"SSIM 0.400, PSNR 12.3 dB at the worst setting\",,,,\n"
              "amy,100,pass,1.0000,inf,0.00,,,,,\n"
              "bob,0,error,,,0.00,,\"class/bob/x.glib:3:1: error: Ortho takes 4 numbers, got 3\",,,\n");
}

// Issue 26: every start a spreadsheet runs as a formula (= + - @) gets a
// quote in front, in every text column; a line break in a name is quoted.
TEST(GradeReport, CsvGuardsEveryFormulaStartAndQuotesLineBreaks) {
    GradeRow plus = row("+cmd|' /C calc'!A0", "wrong", 1), minus = row("-2+3", "wrong", 2),
             at = row("@SUM(A1:A9)", "wrong", 3), eq = row("=1+1", "wrong", 4), nl = row("two\nlines", "wrong", 5),
             cr = row("x\ry", "wrong", 6);
    plus.notes = "+1";
    EXPECT_EQ(gradesCsv({plus, minus, at, eq, nl, cr}),
              "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,computed_score,comment\n"
              "'+cmd|' /C calc'!A0,1,wrong,0.0000,0.00,0.00,'+1,,,,\n"
              "'-2+3,2,wrong,0.0000,0.00,0.00,,,,,\n"
              "'=1+1,4,wrong,0.0000,0.00,0.00,,,,,\n"
              "'@SUM(A1:A9),3,wrong,0.0000,0.00,0.00,,,,,\n"
              "\"two\nlines\",5,wrong,0.0000,0.00,0.00,,,,,\n"
              "\"x\ry\",6,wrong,0.0000,0.00,0.00,,,,,\n");
}

// Issue 29: a tab or a carriage return before the formula still makes a
// formula in some spreadsheets: guarded too (and the CR cell quoted).
TEST(GradeReport, CsvGuardsATabOrCarriageReturnFirst) {
    GradeRow tab = row("\t=1+1", "wrong", 1), cr = row("\r=1+1", "wrong", 2);
    EXPECT_EQ(gradesCsv({tab, cr}),
              "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,computed_score,comment\n"
              "'\t=1+1,1,wrong,0.0000,0.00,0.00,,,,,\n"
              "\"'\r=1+1\",2,wrong,0.0000,0.00,0.00,,,,,\n");
}

// Issue 37: a leading space, a full-width ＝ ＋ － ＠ (spreadsheets read them
// as = + - @), and control bytes from a folder name or a comment (ESC, NUL).
TEST(GradeReport, CsvGuardsSpacesFullWidthSignsAndControlBytes) {
    GradeRow space = row(" =1+1", "wrong", 1), wide = row("\xef\xbc\x9d" "1+1", "wrong", 2),
             esc = row("a\x1b[31mb", "wrong", 3), plain = row("Ada Lovelace", "pass", 4);
    esc.comment = std::string("nul\0here", 8);
    EXPECT_EQ(gradesCsv({space, wide, esc, plain}),
              "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,computed_score,comment\n"
              "' =1+1,1,wrong,0.0000,0.00,0.00,,,,,\n"
              "Ada Lovelace,4,pass,0.0000,0.00,0.00,,,,,\n"
              "a\\x1b[31mb,3,wrong,0.0000,0.00,0.00,,,,,nul\\x00here\n"
              "'\xef\xbc\x9d" "1+1,2,wrong,0.0000,0.00,0.00,,,,,\n");  // in name order, bytewise
}

// Issue 37: a right-to-left override (U+202E) in a folder name turned the
// report around: every place a name stands is isolated.
TEST(GradeReport, ANameIsIsolatedFromTheTextAroundIt) {
    GradeRow r = row("evil\xe2\x80\xae" "gnp.exe", "pass", 100);
    const std::string page = feedbackHtml(r, "rings.glib", {});
    EXPECT_NE(page.find("<title>Feedback: \xe2\x81\xa8" "evil\xe2\x80\xae" "gnp.exe\xe2\x81\xa9"), std::string::npos) << page;
    EXPECT_NE(page.find("<h1><bdi>evil\xe2\x80\xae" "gnp.exe</bdi>: graded against"), std::string::npos) << page;
}

// Issue 26: a student's name goes into attributes (the row's id, the glance
// strip's link): a '"' in it must not end the attribute.
// Issue 29: the teacher's overrides file. Scores replace the computed ones
// (kept beside them), comments go to the report, the CSV and the feedback
// page; bad files get one message at their line.
TEST(GradeReport, OverridesReplaceScoresAndCarryComments) {
    std::map<std::string, Override> o;
    std::string error;
    ASSERT_TRUE(parseOverrides("\xEF\xBB\xBFstudent,score,comment\r\nalice,85,\"right, but \"\"see me\"\"\"\r\n"
                               "bob,,late\n\nnobody,3,\n", "o.csv", o, error)) << error;
    ASSERT_EQ(o.size(), 3u);
    EXPECT_EQ(o["alice"].score, 85);
    EXPECT_EQ(o["alice"].comment, "right, but \"see me\"");
    EXPECT_FALSE(o["bob"].score.has_value());
    std::vector<GradeRow> rows = {row("alice", "wrong", 40), row("bob", "pass", 100)};
    EXPECT_EQ(applyOverrides(rows, o), std::vector<std::string>{"nobody"});
    EXPECT_EQ(rows[0].score, 85);
    EXPECT_EQ(rows[0].computedScore, 40);
    EXPECT_EQ(rows[1].score, 100);
    EXPECT_EQ(rows[1].computedScore, -1);
    EXPECT_EQ(gradesCsv(rows), "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,"
                               "computed_score,comment\n"
                               "alice,85,wrong,0.0000,0.00,0.00,,,,40,\"right, but \"\"see me\"\"\"\n"
                               "bob,100,pass,0.0000,0.00,0.00,,,,,late\n");
    const std::string html = reportRowHtml(rows[0], {});
    EXPECT_NE(html.find("85 <small>(set by hand; computed 40)</small>"), std::string::npos) << html;
    EXPECT_NE(html.find("<p class=comment>Teacher: right, but &quot;see me&quot;</p>"), std::string::npos) << html;
    const std::string page = feedbackHtml(rows[0], "solution.glib", {{"defaults", "data:a", "data:b", "data:c"}});
    EXPECT_NE(page.find("Your teacher: right, but &quot;see me&quot;"), std::string::npos);
    EXPECT_NE(page.find("score 85 (set by your teacher; computed 40)"), std::string::npos);
    EXPECT_NE(page.find("<img src=\"data:c\" alt=\"difference x4\">"), std::string::npos);
    for (auto [text, want] : std::vector<std::pair<std::string, std::string>>{
             {"name,score,comment\n", "o.csv:1: error: the first line must be 'student,score,comment'"},
             {"student,score,comment\nalice,101,\n", "o.csv:2: error: score '101' is not a whole number from 0 to 100"},
             {"student,score,comment\nalice,8.5,\n", "o.csv:2: error: score '8.5' is not a whole number from 0 to 100"},
             {"student,score,comment\na,1,\"two\nlines\"\na,2,\n", "o.csv:4: error: 'a' is named twice"},
             {"student,score,comment\na,1,\"open\n", "o.csv:2: error: a quote that is never closed"},
             {"student,score,comment\na,1\n", "o.csv:2: error: 2 cells; a line is student,score,comment"}}) {
        EXPECT_FALSE(parseOverrides(text, "o.csv", o, error)) << text;
        EXPECT_EQ(error, want) << text;
    }
}

TEST(GradeReport, AQuoteInANameCannotLeaveItsAttribute) {
    EXPECT_EQ(htmlEscape("a \"b\" <c> & 'd'"), "a &quot;b&quot; &lt;c&gt; &amp; &#39;d&#39;");
    GradeRow r = row("x\" onmouseover=\"alert(1)", "pass", 100);
    std::string html = reportRowHtml(r, {});
    EXPECT_EQ(html.find("\" onmouseover"), std::string::npos) << html;
    EXPECT_NE(html.find("id=\"s-x&quot; onmouseover=&quot;alert(1)\""), std::string::npos) << html;
    ReportHeader h;
    h.solution = "sol.glib";
    h.settings = {"defaults"};
    std::string page = reportHtml(h, {r}, {html});
    EXPECT_EQ(page.find("\" onmouseover"), std::string::npos);
    EXPECT_NE(page.find("<a class=pass href=\"#s-x&quot; onmouseover=&quot;alert(1)\">"), std::string::npos);
}

TEST(GradeReport, AFinishedRunDoesNotSayTheRestIsStillRunning) {
    ReportHeader h;
    h.solution = "sol.glib";
    h.settings = {"defaults"};
    h.thresholds = "t";
    h.expected = 2;
    std::vector<GradeRow> rows{row("a", "pass", 100), row("b", "look", 90)};
    std::string page = reportHtml(h, rows, {"", ""});
    EXPECT_NE(page.find("<p class=how>2 submissions · compared at 1 setting: defaults · t · sandbox on</p>"),
              std::string::npos)
        << page;
    h.expected = 3;
    EXPECT_NE(reportHtml(h, rows, {"", ""}).find("<p class=how>2 submissions of 3 (the rest still running) · "),
              std::string::npos);
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
    // The score as nlohmann writes it back (1e300: 1e+300).
    std::string huge = line;
    huge.replace(huge.find("\"score\":91"), 10, "\"score\": 1e300");
    EXPECT_FALSE(parseGradeRecord(huge, back, error));
    EXPECT_EQ(error, "score '1e+300' is not a whole number from 0 to 100");
    EXPECT_FALSE(parseGradeRecord("{\"student\": \"x\"}", back, error));
    EXPECT_EQ(error, "no \"submission\"");
    std::string half = line;
    half.replace(half.find("\"score\":91"), 10, "\"score\": 91.5");
    EXPECT_FALSE(parseGradeRecord(half, back, error));
    EXPECT_EQ(error, "score '91.5' is not a whole number from 0 to 100");
    std::string quoted = line;
    quoted.replace(quoted.find("\"score\":91"), 10, "\"score\": \"91\"");
    EXPECT_FALSE(parseGradeRecord(quoted, back, error));
    EXPECT_EQ(error, "score '\"91\"' is not a whole number from 0 to 100");
    std::string maybe = line;
    maybe.replace(maybe.find("\"verdict\":\"look\""), 16, "\"verdict\": \"maybe\"");
    EXPECT_FALSE(parseGradeRecord(maybe, back, error));
    EXPECT_EQ(error, "verdict 'maybe' is not pass, look, wrong or error");
    std::string word = line;
    word.replace(word.find("\"ssim\":0.912345"), 15, "\"ssim\": \"high\"");
    EXPECT_FALSE(parseGradeRecord(word, back, error));
    EXPECT_EQ(error, "\"ssim\": \"high\" is not a number");
    EXPECT_FALSE(parseGradeRecord("[1, 2]", back, error));
    EXPECT_EQ(error, "not a JSON object");
}

// Issue 25: a record is JSON read by a JSON library. A name written with a
// \u escape (by jq, Python's json.dump, a person) reads back as UTF-8; the
// hand-made reader made each escape one byte ("J\xFCrgen", not UTF-8).
TEST(GradeReport, UnicodeEscapesInARecordReadBackAsUtf8) {
    const std::string line =
        R"({"student": "J\u00fcrgen", "submission": "class/j\u00fcrgen.zip", "script": "", "verdict": "error", )"
        R"("score": 0, "ssim": 0, "psnr": 0, "worst_setting": "", "by_setting": "", "notes": "\u674e\u96f7 \ud83d\ude00", )"
        R"("diagnostics": "", "seconds": 0, "picture": "", "solution": ""})";
    GradeRow back;
    std::string error;
    ASSERT_TRUE(parseGradeRecord(line, back, error)) << error;
    EXPECT_EQ(back.student, "J\xC3\xBCrgen");  // Jürgen
    EXPECT_EQ(back.submission, "class/j\xC3\xBCrgen.zip");
    EXPECT_EQ(back.notes, "\xE6\x9D\x8E\xE9\x9B\xB7 \xF0\x9F\x98\x80");  // 李雷 and an emoji (a surrogate pair)
    // Written back as UTF-8, not as escapes.
    EXPECT_NE(gradeRecord(back).find("\"student\":\"J\xC3\xBCrgen\""), std::string::npos) << gradeRecord(back);
}

// The one rule for numbers JSON lacks (util/json.h): "nan", "inf", "-inf",
// read back as the same values, so --resume keeps them.
TEST(GradeReport, NonFiniteNumbersInARecordReadBack) {
    GradeRow r = row("ann", "error", 0);
    r.ssim = NAN;
    r.psnr = -INFINITY;
    r.seconds = INFINITY;
    const std::string line = gradeRecord(r);
    EXPECT_NE(line.find(R"("ssim":"nan","psnr":"-inf")"), std::string::npos) << line;
    EXPECT_NE(line.find(R"("seconds":"inf")"), std::string::npos) << line;
    GradeRow back;
    std::string error;
    ASSERT_TRUE(parseGradeRecord(line, back, error)) << error;
    EXPECT_TRUE(std::isnan(back.ssim));
    EXPECT_EQ(back.psnr, -INFINITY);
    EXPECT_EQ(back.seconds, INFINITY);
    EXPECT_EQ(gradeRecord(back), line);
}

// A path or a diagnostic quoting a Latin-1 source line is not UTF-8: the
// record is still JSON (each bad byte U+FFFD), never an exception, and it
// reads back.
TEST(GradeReport, TextThatIsNotUtf8StillMakesARecord) {
    GradeRow r = row("ann", "error", 0);
    r.submission = "class/J\xFCrgen";
    r.diagnostics = "a.glib:1:7: error: unknown command 'Gr\xFC\xDF'\n  Color Gr\xFC\xDF\n        ^\n";
    std::string line;
    ASSERT_NO_THROW(line = gradeRecord(r));
    EXPECT_NE(line.find("\"submission\":\"class/J\xEF\xBF\xBDrgen\""), std::string::npos) << line;
    GradeRow back;
    std::string error;
    ASSERT_TRUE(parseGradeRecord(line, back, error)) << error;
    EXPECT_EQ(back.diagnostics, "a.glib:1:7: error: unknown command 'Gr\xEF\xBF\xBD\xEF\xBF\xBD'\n  Color "
                                "Gr\xEF\xBF\xBD\xEF\xBF\xBD\n        ^\n");
    EXPECT_EQ(gradeRecord(back), line);
    // Raw bytes that are not UTF-8 in a record file (a person's edit, an
    // older Glimmer): an error for the line, not a crash.
    EXPECT_FALSE(parseGradeRecord("{\"student\": \"J\xFCrgen\"}", back, error));
    EXPECT_NE(error.find("ill-formed UTF-8"), std::string::npos) << error;
}

// Issue 29: an error row says which error, not one ERROR for all.
TEST(GradeReport, AnErrorRowSaysWhichError) {
    GradeRow timedOut = row("ann", "error", 0), refused = row("bob", "error", 0), plain = row("cy", "error", 0);
    timedOut.notes = "timed out";
    refused.notes = "the zip was refused";
    EXPECT_NE(reportRowHtml(timedOut, {}).find("<span class=v>error: timed out</span>"), std::string::npos);
    EXPECT_NE(reportRowHtml(refused, {}).find("<span class=v>error: the zip was refused</span>"), std::string::npos);
    EXPECT_NE(reportRowHtml(plain, {}).find("<span class=v>error</span>"), std::string::npos);
    EXPECT_NE(reportRowHtml(row("di", "pass", 100), {}).find("<span class=v>pass</span>"), std::string::npos);
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
