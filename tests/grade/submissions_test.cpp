// Which entries of a class folder are submissions, and which script in each.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/test_folder.h"
#include "grade/submissions.h"

namespace glimmer {
namespace {
namespace fs = std::filesystem;

void touch(const fs::path& p) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "x";
}

TEST(Submissions, AClassFolderHoldsOneSubmissionPerFolderAndZip) {
    testing::TestFolder t("subs");
    touch(t.path / "class/carol/bloom.glib");
    touch(t.path / "class/alice/hw/bloom.glib");
    touch(t.path / "class/bob.zip");
    touch(t.path / "class/notes.txt");
    touch(t.path / "class/.git/x.glib");
    touch(t.path / "class/__MACOSX/y.glib");
    std::vector<std::string> errors;
    auto subs = listSubmissions({(t.path / "class").string()}, errors);
    EXPECT_TRUE(errors.empty());
    ASSERT_EQ(subs.size(), 3u);
    EXPECT_EQ(subs[0].name, "alice");
    EXPECT_EQ(subs[1].name, "bob");
    EXPECT_TRUE(subs[1].zip);
    EXPECT_EQ(subs[2].name, "carol");
    EXPECT_EQ(subs[2].path, (t.path / "class/carol").string());
}

TEST(Submissions, AFolderWithAScriptIsOneSubmission) {
    testing::TestFolder t("subs");
    touch(t.path / "dan/bloom.glib");
    std::vector<std::string> errors;
    auto subs = listSubmissions({(t.path / "dan").string() + "/", (t.path / "nothing").string()}, errors);
    ASSERT_EQ(subs.size(), 1u);
    EXPECT_EQ(subs[0].name, "dan");
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], (t.path / "nothing").string() + ": error: not a folder, a .zip or a .glib script");
}

TEST(Submissions, TheScriptIsFoundInsideFolders) {
    testing::TestFolder t("subs");
    touch(t.path / "alice/hw3/bloom.glib");
    touch(t.path / "alice/hw3/bloom.frag");
    std::string error;
    EXPECT_EQ(findScript((t.path / "alice").string(), error), (t.path / "alice/hw3/bloom.glib").string());
    EXPECT_EQ(error, "");
}

TEST(Submissions, NoScriptOrTwoScriptsAreNamed) {
    testing::TestFolder t("subs");
    touch(t.path / "bob/readme.txt");
    touch(t.path / "eve/a.glib");
    touch(t.path / "eve/old/b.glib");
    touch(t.path / "eve/.trash/c.glib");
    std::string error;
    EXPECT_EQ(findScript((t.path / "bob").string(), error), "");
    // What was there instead is named (issue 29).
    EXPECT_EQ(error, (t.path / "bob").string() + ": error: no .glib script in this submission; it holds readme.txt");
    EXPECT_EQ(findScript((t.path / "eve").string(), error), "");
    EXPECT_EQ(error, (t.path / "eve").string() + ": error: 2 .glib scripts (a.glib, old/b.glib); keep one");
}

// A script three folders down (a course folder in a zip's folder) is found
// (issue 29: it was "no .glib script"); past eight levels nothing is searched.
TEST(Submissions, ScriptsAreFoundUpToEightFoldersDown) {
    testing::TestFolder t("subs");
    touch(t.path / "f/week3/hw/bloom/ok.glib");
    touch(t.path / "f/1/2/3/4/5/6/7/8/too_deep.glib");
    std::string error;
    EXPECT_EQ(findScript((t.path / "f").string(), error), (t.path / "f/week3/hw/bloom/ok.glib").string()) << error;
    touch(t.path / "g/1/2/3/4/5/6/7/seven.glib");
    EXPECT_EQ(findScript((t.path / "g").string(), error), (t.path / "g/1/2/3/4/5/6/7/seven.glib").string()) << error;
}

}  // namespace
}  // namespace glimmer
