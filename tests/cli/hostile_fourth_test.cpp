// Hostile input, fourth pass (issue 37): what a file or a name brings is
// printed escaped, an empty option value is a usage error, a teacher's long
// list of unknown names is folded, and a time-out names what was running.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

const fs::path kSolution = fs::path(GLIMMER_TEST_DATA) / "grading" / "solution";

void copySolution(const fs::path& to, const std::string& frag = "") {
    fs::create_directories(to);
    for (const char* f : {"rings.glib", "rings.frag", "st.vert"}) fs::copy_file(kSolution / f, to / f);
    if (!frag.empty()) std::ofstream(to / "rings.frag", std::ios::binary | std::ios::trunc) << frag;
}

// A control byte a terminal would act on: C0 but newline and tab, DEL, a C1
// character in UTF-8 (U+0080..U+009F), or a byte 0x80..0x9f that is no part
// of a whole UTF-8 character (CSI 0x9b to an 8-bit terminal). Whole UTF-8
// characters (Cyrillic ћ is D1 9B) are text.
bool hasRawControl(const std::string& text) {
    for (size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) return true;
            ++i;
            continue;
        }
        const size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
        bool whole = n > 0 && i + n <= text.size();
        for (size_t k = 1; whole && k < n; ++k) whole = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
        if (whole && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) <= 0x9f) return true;  // C1
        if (!whole && c <= 0x9f) return true;
        i += whole ? n : 1;
    }
    return false;
}

// "ESC c" is a full terminal reset: twice in a script, the folded warning
// printed it raw; a lone 0x9b byte (CSI in an 8-bit terminal) too.
TEST(CliHostileFourth, FoldedWarningsAndLoneHighBytesAreEscaped) {
    TempDir dir;
    std::ofstream(dir.file("e.glib"), std::ios::binary) << "##OpenGL GLIB\n\x1b" "c\n\x1b" "c\nx\x9by\nOrtho -1 1 -1 1\n";
    auto r = runGlimmer({"check", dir.file("e.glib")});
    EXPECT_FALSE(hasRawControl(r.err)) << r.err;
    EXPECT_EQ(countOf(r.err, "3 warnings like this one (line 2 first): unknown command '\\x1bc'; line ignored"), 1)
        << r.err;
    auto v = runGlimmer({"-v", "check", dir.file("e.glib")});
    EXPECT_FALSE(hasRawControl(v.err)) << v.err;
    EXPECT_EQ(countOf(v.err, "unknown command 'x\\x9by'"), 1) << v.err;
    // Whole UTF-8 characters stay as written.
    std::ofstream(dir.file("u.glib"), std::ios::binary) << "J\xc3\xbcrgen Gro\xc3\x9f\n";
    auto u = runGlimmer({"-v", "check", dir.file("u.glib")});
    EXPECT_EQ(countOf(u.err, "unknown command 'J\xc3\xbcrgen'"), 1) << u.err;
}

// A folder name with ESC in it reaches every diagnostic as \x1b.
TEST(CliHostileFourth, AFileNameIsEscapedInDiagnostics) {
    TempDir dir;
    const fs::path folder = dir.path() / "a\x1b]0;owned\x07";
    fs::create_directories(folder);
    std::ofstream(folder / "s.glib") << "Ortho -1 1 -1\n";
    auto r = runGlimmer({"check", (folder / "s.glib").string()});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_FALSE(hasRawControl(r.err)) << r.err;
    EXPECT_NE(r.err.find("a\\x1b]0;owned\\x07/s.glib:1:1: error:"), std::string::npos) << r.err;
}

TEST(CliHostileFourth, AnEmptyWatchOrWatchRangeIsAUsageError) {
    const std::string script = std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib";
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"render", script, "-o", "/dev/null/x.png", "--watch", ""},
             {"render", script, "-o", "/dev/null/x.png", "--watch", "bloom.frag:12:rgbblur", "--watch-range", ""},
             {"check", script, "--watch", ""}}) {
        auto r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 2) << args.back() << r.err;
        EXPECT_NE(r.err.find("an empty value; give one or leave the option out"), std::string::npos) << r.err;
    }
}

// A grading run stopped while the driver still compiles the submission's
// shader says so, not "at setting defaults (1 of N)".
TEST(CliHostileFourth, AGradingTimeOutWhileCompilingSaysSo) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    std::string frag = readAll(kSolution / "rings.frag");
    std::string macros = "#define A0 (vST.s * 1.0001)\n";
    for (int k = 1; k <= 22; ++k)
        macros += "#define A" + std::to_string(k) + " (A" + std::to_string(k - 1) + " + A" + std::to_string(k - 1) + ")\n";
    frag.insert(frag.find("void main"), macros);
    frag.insert(frag.find("gl_FragColor = ") , "float huge = A22;\n    ");
    copySolution(cls / "bigshader", frag);
    auto r = runGlimmer({"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o",
                         (dir.path() / "out").string(), "--size", "32x32", "--backend", "osmesa", "--timeout", "2"},
                        120);
    const std::string csv = readAll(dir.path() / "out" / "grades.csv");
    EXPECT_NE(csv.find("bigshader,0,error,,,"), std::string::npos) << csv << r.err;
    EXPECT_NE(csv.find("timed out while loading and compiling"), std::string::npos) << csv;
    EXPECT_NE(csv.find("stopped after 2 s (--timeout 2) while loading and compiling the script"), std::string::npos) << csv;
}

// 99,999 unknown names in --overrides printed 9.3 MB of warnings.
TEST(CliHostileFourth, UnknownOverrideNamesAreFolded) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    copySolution(cls / "right");
    std::ofstream csv(dir.path() / "overrides.csv");
    csv << "student,score,comment\n";
    for (int k = 0; k < 5000; ++k) csv << "ghost" << k << ",1,\n";
    csv.close();
    auto r = runGlimmer({"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o",
                         (dir.path() / "out").string(), "--size", "32x32", "--backend", "osmesa", "--overrides",
                         (dir.path() / "overrides.csv").string()},
                        120);
    EXPECT_EQ(r.exitCode, 0) << r.err.substr(0, 2000);
    EXPECT_EQ(countOf(r.err, "whom no row has (as the report names students)"), 5) << r.err.substr(0, 2000);
    EXPECT_EQ(countOf(r.err, "glimmer: warning: --overrides names 4995 more whom no row has"), 1) << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), 4000u);
}

// A student who kept the old version beside the new one: the script named
// like the solution's is graded, and the row says which and why.
TEST(CliHostileFourth, OfTwoScriptsTheOneNamedLikeTheSolutionsIsGraded) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    copySolution(cls / "ana");
    std::ofstream(cls / "ana" / "rings_old.glib") << "Ortho -1 1 -1\n";
    copySolution(cls / "bo");
    fs::rename(cls / "bo" / "rings.glib", cls / "bo" / "mine.glib");
    fs::copy_file(cls / "bo" / "mine.glib", cls / "bo" / "mine2.glib");
    auto r = runGlimmer({"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o",
                         (dir.path() / "out").string(), "--size", "32x32", "--backend", "osmesa"},
                        120);
    const std::string csv = readAll(dir.path() / "out" / "grades.csv");
    EXPECT_NE(csv.find("\nana,100,pass,1.0000,inf,"), std::string::npos) << csv << r.err;
    EXPECT_NE(csv.find("2 .glib scripts (rings.glib, rings_old.glib): graded rings.glib, named like the solution's"),
              std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbo,0,error,,,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("2 .glib scripts (mine.glib, mine2.glib); keep one"), std::string::npos) << csv;
}

// --resume compares the solution's content, not only its path.
TEST(CliHostileFourth, ResumeRefusesASolutionChangedUnderTheSameName) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", sol = dir.path() / "solution";
    copySolution(cls / "ana");
    copySolution(sol);
    auto grade = [&](bool resume) {
        std::vector<std::string> args = {"batch", cls.string(), "--reference", (sol / "rings.glib").string(), "-o",
                                         (dir.path() / "out").string(), "--size", "32x32", "--backend", "osmesa"};
        if (resume) args.push_back("--resume");
        return runGlimmer(args, 120);
    };
    auto first = grade(false);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    auto same = grade(true);
    EXPECT_EQ(same.exitCode, 0) << same.err;  // nothing changed: resumes
    std::string frag = readAll(sol / "rings.frag");
    std::ofstream(sol / "rings.frag", std::ios::binary | std::ios::trunc) << frag << "\n// fixed the tint\n";
    auto changed = grade(true);
    EXPECT_EQ(changed.exitCode, 2) << changed.err;
    EXPECT_NE(changed.err.find("was graded with another solution (the same name, other content)"), std::string::npos)
        << changed.err;
}

// The output guard's holes (issue 37): a frame pattern whose first frame is
// an input, a path through a folder that is not there, a watch's file, a
// FIFO, and names under /dev. Each refused before anything is drawn, the
// input left as it was.
TEST(CliHostileFourth, NoOutputNameReachesAnInputOrASpecialFile) {
    TempDir dir;
    const std::string solid = dir.file("solid.png");
    ASSERT_EQ(runGlimmer({"-q", "render", std::string(GLIMMER_SOURCE_DIR) + "/" + cliData("colour.glib"), "-o", solid,
                          "--size", "8x8", "--backend", "osmesa"}).exitCode, 0);
    fs::copy_file(solid, dir.file("frame0.png"));
    fs::copy_file(solid, dir.file("in%d.png"));
    fs::copy_file(std::string(GLIMMER_SOURCE_DIR) + "/" + cliData("plain.vert"), dir.file("plain.vert"));
    writeFile(dir, "bright.frag", "uniform sampler2D uA, uB;\nvarying vec2 vST;\n"
                                  "void main() { gl_FragColor = texture2D(uA, vST) + texture2D(uB, vST); }\n");
    const std::string script = writeFile(dir, "p.glib", "Texture2D 5 frame0.png\nTexture2D 6 in%d.png\n"
                                                        "Vertex plain.vert\nFragment bright.frag\nProgram P uA 5 uB 6\n"
                                                        "QuadXY 0 1\n");
    const std::string frame0 = readAll(dir.file("frame0.png")), frag = readAll(dir.file("bright.frag"));
    auto refused = [&](std::vector<std::string> extra, const std::string& message) {
        std::vector<std::string> args = {"render", script, "--size", "8x8", "--backend", "osmesa", "--timeout", "20"};
        args.insert(args.end(), extra.begin(), extra.end());
        auto r = runGlimmer(args, 30);
        EXPECT_FALSE(r.timedOut) << extra[1];
        EXPECT_EQ(r.exitCode, 2) << extra[1] << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    };
    refused({"-o", dir.file("frame%d.png")}, ": that is 'frame0.png', which the script reads");
    refused({"-o", dir.file("x%d/../bright.frag")}, ": that is 'bright.frag', which the script reads");
    refused({"-o", dir.file("in%d.png"), "--watch", "bright.frag:3:vST"}, ": that is 'in%d.png', which the script reads");
    ASSERT_EQ(::mkfifo(dir.file("pipe.png").c_str(), 0600), 0);
    refused({"-o", dir.file("pipe.png")}, "that is a FIFO (writing would wait for a reader)");
    refused({"-o", "/dev/full.png"}, "-o /dev/full.png: that is under /dev/, not a file");
    refused({"-o", "/dev/null"}, "-o /dev/null: that is a device or other special file");
    EXPECT_FALSE(fs::exists("/dev/full.png"));
    EXPECT_EQ(readAll(dir.file("frame0.png")), frame0);
    EXPECT_EQ(readAll(dir.file("bright.frag")), frag);
    // A name that is none of these still gets its picture.
    auto ok = runGlimmer({"render", script, "--size", "8x8", "--backend", "osmesa", "-o", dir.file("out%d.png")});
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_TRUE(fs::exists(dir.file("out0.png")));
}

// A correct submission in a folder of 250 characters was "error, cannot
// write ... File name too long": its pictures and page get a shorter stem.
TEST(CliHostileFourth, ASubmissionInAFolderOfALongNameIsGraded) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    const std::string longName(250, 'L');
    copySolution(cls / longName);
    auto r = runGlimmer({"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o",
                         (dir.path() / "out").string(), "--size", "32x32", "--backend", "osmesa"},
                        120);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string csv = readAll(dir.path() / "out" / "grades.csv");
    EXPECT_NE(csv.find("\n" + std::string(120, 'L') + ",100,pass,"), std::string::npos) << csv;
    EXPECT_TRUE(fs::exists(dir.path() / "out" / "feedback" / (std::string(120, 'L') + ".html")));
}

// A watched pass that runs out of time is named by its line, as any pass
// is (it was "while loading and compiling the script", with no line).
TEST(CliHostileFourth, ASlowWatchedPassIsNamedByItsLine) {
    TempDir dir;
    const std::string script = writeRunawayScript(dir);
    auto r = runGlimmer({"render", script, "--backend", "osmesa", "--size", "64x64", "--timeout", "2", "--watch",
                         "slow.frag:48:a", "-o", dir.file("w.png")},
                        60);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(script + ":9:1: error: stopped after 2 s (--timeout 2): the pass that starts here was still "),
              std::string::npos) << r.err;
}

// Names as written (issue 37): "Jürgen Groß" keeps its space in the student
// column, and a hidden folder of a class is said, not skipped in silence.
TEST(CliHostileFourth, NamesAsWrittenAndHiddenHandInsSaid) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    copySolution(cls / "J\xc3\xbcrgen Gro\xc3\x9f");
    copySolution(cls / ".late");
    copySolution(cls / "   ");
    auto r = runGlimmer({"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o",
                         (dir.path() / "out").string(), "--size", "32x32", "--backend", "osmesa"},
                        120);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string csv = readAll(dir.path() / "out" / "grades.csv");
    EXPECT_NE(csv.find("\nJ\xc3\xbcrgen Gro\xc3\x9f,100,pass,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\n(3 spaces),100,pass,"), std::string::npos) << csv;  // was "script"
    EXPECT_EQ(countOf(r.err, "glimmer: warning: " + (cls / ".late").string() +
                                 ": skipped, its name starts with '.' (hidden); rename it to grade it\n"), 1) << r.err;
}

// 200 KB of random bytes as a script on standard input printed 53 raw 0x9b
// bytes: now nothing of it reaches the terminal unescaped.
TEST(CliHostileFourth, RandomBytesOnStandardInputPrintNoRawControl) {
    TempDir dir;
    std::string bytes;
    unsigned x = 12345;
    for (int k = 0; k < 200000; ++k) {
        x = x * 1103515245u + 12345u;
        bytes += char((x >> 16) & 0xff);
    }
    std::ofstream(dir.file("random.bin"), std::ios::binary) << bytes;
    auto r = runGlimmerWithInput({"render", "-", "-o", dir.file("o.png"), "--size", "8x8", "--backend", "osmesa"},
                                 dir.file("random.bin"));
    EXPECT_FALSE(r.timedOut);
    EXPECT_FALSE(hasRawControl(r.err)) << r.err.substr(0, 3000);
    auto v = runGlimmerWithInput({"-v", "render", "-", "-o", dir.file("o.png"), "--size", "8x8", "--backend", "osmesa"},
                                 dir.file("random.bin"));
    EXPECT_FALSE(hasRawControl(v.err)) << v.err.substr(0, 3000);
}

}  // namespace
}  // namespace glimmer_cli
