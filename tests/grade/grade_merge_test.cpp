// Reading a grading folder back: the run's header, records cut off by a
// kill, and shards joined with every student exactly once.
#include <gtest/gtest.h>

#include "grade/grade_merge.h"

namespace glimmer {
namespace {

GradeRow row(const std::string& who, int score) {
    GradeRow r;
    r.student = who;
    r.verdict = "pass";
    r.score = score;
    return r;
}

TEST(GradeMerge, TheHeaderReadsBack) {
    ReportHeader h;
    h.solution = "sol/solution.glib";
    h.settings = {"defaults", "uA=0"};
    h.thresholds = "pass: SSIM >= 0.95";
    h.sandbox = false;
    std::string text = runHeaderText(h, {"alice", "bob"});
    ReportHeader back;
    std::vector<std::string> students;
    std::string error;
    ASSERT_TRUE(parseRunHeader(text, back, students, error)) << error;
    EXPECT_EQ(runHeaderText(back, students), text);
    EXPECT_EQ(back.expected, 2);
    EXPECT_FALSE(parseRunHeader("solution: x\ncolour: red\n", back, students, error));
    EXPECT_EQ(error, "line 2: unknown key 'colour'");
}

TEST(GradeMerge, ALastLineCutOffByAKillIsDroppedAndOthersAreErrors) {
    std::string a = gradeRecord(row("alice", 90)), b = gradeRecord(row("bob", 80));
    std::vector<GradeRow> rows;
    std::string error;
    ASSERT_TRUE(parseRecords(a + "\n" + b.substr(0, 20), "g.jsonl", rows, error)) << error;
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].student, "alice");
    rows.clear();
    EXPECT_FALSE(parseRecords(b.substr(0, 20) + "\n" + a + "\n", "g.jsonl", rows, error));
    EXPECT_EQ(error, "g.jsonl:1: error: at column 21: syntax error while parsing object key - invalid string: "
                     "missing closing quote; last read: '\"su'; expected string literal");
    rows.clear();  // a whole last line (it ends with a newline) was not cut off by a kill: an error
    EXPECT_FALSE(parseRecords(a + "\n" + b.substr(0, 20) + "\n", "g.jsonl", rows, error));
    EXPECT_EQ(error, "g.jsonl:2: error: at column 21: syntax error while parsing object key - invalid string: "
                     "missing closing quote; last read: '\"su'; expected string literal");
    rows.clear();  // graded again after a resume: the later record stands
    ASSERT_TRUE(parseRecords(a + "\n" + gradeRecord(row("alice", 95)) + "\n", "g.jsonl", rows, error));
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].score, 95);
}

TEST(GradeMerge, EveryStudentExactlyOnce) {
    std::vector<GradeRow> merged;
    std::vector<std::string> errors;
    EXPECT_TRUE(mergeShardRows({{row("a", 1), row("c", 3)}, {row("b", 2)}}, {"a", "b", "c"}, merged, errors));
    EXPECT_EQ(merged.size(), 3u);
    EXPECT_FALSE(mergeShardRows({{row("a", 1), row("z", 3)}, {row("a", 2)}}, {"a", "b"}, merged, errors));
    ASSERT_EQ(errors.size(), 3u);
    EXPECT_EQ(errors[0], "a: graded by 2 shards");
    EXPECT_EQ(errors[1], "b: in no shard's results");
    EXPECT_EQ(errors[2], "z: not in the class list");
}

}  // namespace
}  // namespace glimmer
