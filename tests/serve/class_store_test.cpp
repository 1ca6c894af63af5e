// What `glimmer serve` keeps (serve/class_store.h), the roster it reads
// (serve/roster.h), its tokens and its rate limit: each asserted on what a
// teacher or student would see (a file's text at a version, a grading
// order, an exact message).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "serve/class_store.h"
#include "serve/random_token.h"
#include "serve/request_limits.h"
#include "serve/roster.h"

namespace fs = std::filesystem;
using namespace glimmer;

namespace {

struct StoreTest : ::testing::Test {
    fs::path dir;
    ClassStore store;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("glimmer-store-" + randomToken(6));
        fs::create_directories(dir);
        std::string why;
        ASSERT_TRUE(store.open((dir / "class.sqlite").string(), why)) << why;
    }
    void TearDown() override { fs::remove_all(dir); }
};

TEST_F(StoreTest, EveryVersionIsKeptAndReadBackAsOfItsTime) {
    const Student ada = *store.studentNamed("Ada", true);
    const auto v1 = store.save(ada.id, {{"blur.frag", "one"}, {"blur.glib", "script"}}, "drawn");
    const auto v2 = store.save(ada.id, {{"blur.frag", "two"}}, "drawn");
    const auto v3 = store.save(ada.id, {{"blur.frag", "three"}, {"blur.glib", "script"}}, "1 error");
    EXPECT_LT(v1, v2);
    EXPECT_LT(v2, v3);
    EXPECT_EQ(store.filesAt(ada.id, v1), (FileTexts{{"blur.frag", "one"}, {"blur.glib", "script"}}));
    EXPECT_EQ(store.filesAt(ada.id, v2), (FileTexts{{"blur.frag", "two"}, {"blur.glib", "script"}}));
    EXPECT_EQ(store.filesAt(ada.id), (FileTexts{{"blur.frag", "three"}, {"blur.glib", "script"}}));
    EXPECT_EQ(store.latestVersion(ada.id), v3);
}

TEST_F(StoreTest, ASaveThatChangesNothingMakesNoVersion) {
    const Student ada = *store.studentNamed("Ada", true);
    const auto v1 = store.save(ada.id, {{"a.frag", "x"}}, "drawn");
    EXPECT_EQ(store.save(ada.id, {{"a.frag", "x"}}, "drawn"), v1);
    EXPECT_GT(store.save(ada.id, {{"a.frag", "x"}}, "1 error"), v1);  // the page's verdict changed: the teacher sees it
}

TEST_F(StoreTest, StudentsSeeOnlyTheirOwnFiles) {
    const Student ada = *store.studentNamed("Ada", true), bob = *store.studentNamed("Bob", true);
    store.save(ada.id, {{"a.frag", "ada's"}}, "");
    EXPECT_EQ(store.filesAt(bob.id), FileTexts{});
    EXPECT_EQ(store.studentByToken(bob.token)->name, "Bob");
    EXPECT_FALSE(store.studentByToken(std::string(32, '0')));
    EXPECT_NE(ada.token, bob.token);
}

TEST_F(StoreTest, ANameKeepsItsStudentAndTwoNamesNeverShareAFolder) {
    const Student a = *store.studentNamed("Ada L", true);
    EXPECT_EQ(store.studentNamed("Ada L", true)->id, a.id);
    EXPECT_EQ(store.studentNamed("Ada L", false)->token, a.token);
    EXPECT_FALSE(store.studentNamed("Nobody", false));
    const Student b = *store.studentNamed("Ada_L", true);  // the same folder name once made
    EXPECT_EQ(a.folder, "Ada_L");
    EXPECT_EQ(b.folder, "Ada_L-2");
}

TEST_F(StoreTest, GradingTakesOneHandInPerStudentARunOldestFirstAndAgainAfterARestart) {
    const Student ada = *store.studentNamed("Ada", true), bob = *store.studentNamed("Bob", true);
    const auto h1 = store.handIn(ada.id), h2 = store.handIn(ada.id), h3 = store.handIn(bob.id);
    std::vector<HandIn> run = store.takeQueued(10);
    ASSERT_EQ(run.size(), 2u);
    EXPECT_EQ(run[0].id, h1);
    EXPECT_EQ(run[1].id, h3);
    // Cut off mid-grading (the server killed): still to grade, with what was not taken.
    run = store.takeQueued(10);
    ASSERT_EQ(run.size(), 2u);
    EXPECT_EQ(run[0].id, h1);
    store.finishHandIn(h1, "graded", "pass", 100, "");
    store.finishHandIn(h3, "graded", "wrong", 12, "SSIM 0.1");
    run = store.takeQueued(10);
    ASSERT_EQ(run.size(), 1u);
    EXPECT_EQ(run[0].id, h2);
    EXPECT_EQ(store.handInById(h3)->verdict, "wrong");
    EXPECT_EQ(store.handInById(h3)->score, 12);
}

TEST_F(StoreTest, AHandInIsOfTheVersionSavedWhenItWasMade) {
    const Student ada = *store.studentNamed("Ada", true);
    store.save(ada.id, {{"a.frag", "handed in"}}, "");
    const auto h = store.handIn(ada.id);
    store.save(ada.id, {{"a.frag", "edited after"}}, "");
    EXPECT_EQ(store.filesAt(ada.id, store.handInById(h)->version), (FileTexts{{"a.frag", "handed in"}}));
}

TEST_F(StoreTest, WhatIsCommittedIsThereWhenTheDatabaseIsOpenedAgain) {
    const Student ada = *store.studentNamed("Ada", true);
    store.save(ada.id, {{"a.frag", "kept"}}, "");
    const std::string teacher = store.teacherToken(), code = store.classCode();
    ClassStore again;
    std::string why;
    ASSERT_TRUE(again.open((dir / "class.sqlite").string(), why)) << why;
    EXPECT_EQ(again.filesAt(ada.id), (FileTexts{{"a.frag", "kept"}}));
    EXPECT_EQ(again.teacherToken(), teacher);
    EXPECT_EQ(again.classCode(), code);
}

TEST(FolderName, AsGradingNamesTheStudent) {
    EXPECT_EQ(folderNameFor("Lovelace, Ada"), "Lovelace__Ada");
    EXPECT_EQ(folderNameFor("Émile Zola"), "Émile_Zola");
    EXPECT_EQ(folderNameFor("../../etc"), "etc");
    EXPECT_EQ(folderNameFor("..."), "student");
    EXPECT_EQ(folderNameFor("a\xC2\x85z"), "a__z");  // a C1 control is not a letter
    EXPECT_EQ(folderNameFor("\xFF\xFE"), "student");
    EXPECT_LE(folderNameFor(std::string(300, 'x')).size(), 60u);
}

TEST(Tokens, AreLongRandomAndHex) {
    std::set<std::string> seen;
    for (int i = 0; i < 200; ++i) {
        const std::string t = randomToken();
        ASSERT_EQ(t.size(), 32u);
        ASSERT_EQ(t.find_first_not_of("0123456789abcdef"), std::string::npos);
        seen.insert(t);
    }
    EXPECT_EQ(seen.size(), 200u);
    const std::string code = randomClassCode();
    ASSERT_EQ(code.size(), 9u);
    EXPECT_EQ(code[4], '-');
    EXPECT_EQ(code.find_first_of("01OIL"), std::string::npos);
}

TEST(Roster, NamesWithAHeaderQuotesAndBlankLines) {
    std::vector<std::string> names;
    std::string why;
    ASSERT_TRUE(parseRoster("name,email\n\"Lovelace, Ada\",ada@x\n\nBob \r\n", "r.csv", names, why)) << why;
    EXPECT_EQ(names, (std::vector<std::string>{"Lovelace, Ada", "Bob"}));
}

TEST(Roster, RefusesInCompilerStyle) {
    std::vector<std::string> names;
    std::string why;
    EXPECT_FALSE(parseRoster("Ada\n,b@x\n", "r.csv", names, why));
    EXPECT_EQ(why, "r.csv:2:1: error: no name before the first comma\n,b@x\n^");
    names.clear();
    EXPECT_FALSE(parseRoster("Ada\n" + std::string(61, 'x') + "\n", "r.csv", names, why));
    EXPECT_EQ(why.substr(0, why.find('\n')), "r.csv:2:1: error: a name is at most 60 bytes");
    names.clear();
    EXPECT_FALSE(parseRoster("\n\n", "r.csv", names, why));
    EXPECT_EQ(why, "r.csv: error: no student in it");
}

TEST(RequestLimits, ABurstThenTheRate) {
    RequestLimits limits(1, 5);
    int allowed = 0;
    for (int i = 0; i < 20; ++i) allowed += limits.allow("a");
    EXPECT_EQ(allowed, 5);
    EXPECT_TRUE(limits.allow("b"));  // one client's flood is its own
}

}  // namespace
