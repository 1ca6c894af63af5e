// glimmer batch --reference: a generated class graded against the solution
// in tests/data/grading/solution, one submission for each case a teacher
// meets; --resume after a kill; shards joined by batch-merge.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zip.h>

#include <chrono>
#include <thread>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "run_glimmer.h"

namespace {

namespace fs = std::filesystem;
using glimmer_cli::countOf;
using glimmer_cli::readAll;
using glimmer_cli::runGlimmer;
using glimmer_cli::TempDir;

const fs::path kSolution = fs::path(GLIMMER_TEST_DATA) / "grading" / "solution";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// A student's folder: the solution's files, the fragment shader (and the
// script) changed as given.
void student(const fs::path& dir, const std::string& frag, const std::string& glib = "") {
    fs::create_directories(dir);
    fs::copy_file(kSolution / "st.vert", dir / "st.vert");
    std::ofstream(dir / "rings.frag") << frag;
    std::ofstream(dir / "rings.glib") << (glib.empty() ? readAll(kSolution / "rings.glib") : glib);
}

void zipFolder(const fs::path& zipPath, const std::map<std::string, std::string>& files) {
    int err = 0;
    zip_t* z = zip_open(zipPath.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
    ASSERT_NE(z, nullptr);
    std::vector<std::string> keep;  // zip_source_buffer reads them at zip_close: no reallocation may move them
    keep.reserve(files.size());
    for (const auto& [name, data] : files) {
        keep.push_back(data);
        zip_file_add(z, name.c_str(), zip_source_buffer(z, keep.back().data(), keep.back().size(), 0), 0);
    }
    ASSERT_EQ(zip_close(z), 0);
}

// The cells of one CSV line as written (quotes kept), split at the commas
// outside quotes.
std::vector<std::string> rawCells(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        if (c == ',' && !quoted) cells.emplace_back();
        else cells.back() += c;
    }
    return cells;
}

const std::string kCsvHeader =
    "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,computed_score,comment";

// student -> its CSV line without the seconds column (times differ run to
// run) and without the submission's path and the teacher's columns:
// "score,verdict,ssim,psnr|notes,first_diagnostic".
std::map<std::string, std::string> csvRows(const fs::path& csv) {
    std::map<std::string, std::string> out;
    std::istringstream in(readAll(csv));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, kCsvHeader);
    while (std::getline(in, line)) {
        auto c = rawCells(line);
        EXPECT_EQ(c.size(), 11u) << line;
        if (c.size() < 8) continue;
        out[c[0]] = c[1] + "," + c[2] + "," + c[3] + "," + c[4] + "|" + c[6] + "," + c[7];
    }
    return out;
}

// student -> its cell in column `column` (raw, quotes kept).
std::map<std::string, std::string> csvColumn(const fs::path& csv, const std::string& column) {
    std::map<std::string, std::string> out;
    std::istringstream in(readAll(csv));
    std::string line;
    std::getline(in, line);
    auto names = rawCells(line);
    const size_t k = size_t(std::find(names.begin(), names.end(), column) - names.begin());
    while (std::getline(in, line)) {
        auto c = rawCells(line);
        if (k < c.size()) out[c[0]] = c[k];
    }
    return out;
}

std::vector<std::string> gradeArgs(const fs::path& cls, const fs::path& out) {
    return {"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o", out.string(),
            "--size", "128x128", "--backend", "osmesa", "--timeout", "3", "--jobs", "2"};
}

// The class of the cases.
void makeClass(const fs::path& cls) {
    const std::string frag = readAll(kSolution / "rings.frag");
    student(cls / "right", frag);
    student(cls / "shifted", replaced(frag, "length(vST - vec2(0.5))", "length(vST + vec2(1.0/128.0, 0.0) - vec2(0.5))"));
    student(cls / "weights", replaced(frag, "(0.5 + 0.5 * uTint)", "(0.52 + 0.48 * uTint)"));
    student(cls / "painted", replaced(frag, "6.2831853 * uFreq", "6.2831853 * 6.0"));  // right only at uFreq's default
    student(cls / "blank", replaced(frag, "mix(cool, warm, ring) * (0.5 + 0.5 * uTint)", "vec3(0.0)"));
    student(cls / "broken", replaced(frag, "float r = ", "float r = = "));
    std::string body;
    for (int k = 0; k < 40; ++k) body += "        a = sin(a * 1.0001 + float(i) * 1e-5 + vST.s + " + std::to_string(k) + ".0);\n";
    student(cls / "slow", replaced(frag, "    gl_FragColor = ", "    float a = r;\n    for (int i = 0; i < 60000; ++i) {\n" +
                                                                  body + "    }\n    gl_FragColor = vec4(a) + "));
    student(cls / "untinted", frag, replaced(readAll(kSolution / "rings.glib"), " uTint <0. 0.5 1.>", ""));
    fs::create_directories(cls / "empty");
    std::ofstream(cls / "empty" / "notes.txt") << "forgot the script\n";
    student(cls / "twice", frag);
    fs::copy_file(cls / "twice" / "rings.glib", cls / "twice" / "old.glib");
    zipFolder(cls / "zipped.zip", {{"hw/st.vert", readAll(kSolution / "st.vert")},
                                   {"hw/rings.frag", frag},
                                   {"hw/rings.glib", readAll(kSolution / "rings.glib")}});
    zipFolder(cls / "evil.zip", {{"rings.glib", "Ortho -1 1 -1 1\n"}, {"../escaped.txt", "x"}});
}

TEST(CliGrade, EachKindOfSubmissionGetsItsVerdict) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", out = dir.path() / "out";
    makeClass(cls);
    auto r = runGlimmer(gradeArgs(cls, out), 120);
    ASSERT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 1) << r.err;  // some submissions could not be graded
    EXPECT_EQ(countOf(r.err, "wrote " + (out / "report.html").string() +
                                 " (12 submissions: 4 pass, 1 look, 3 wrong, 4 error), " +
                                 (out / "grades.csv").string()), 1) << r.err;
    EXPECT_EQ(countOf(r.err, "--no-sandbox"), 0);
    EXPECT_FALSE(fs::exists(dir.path() / "escaped.txt"));
    auto rows = csvRows(out / "grades.csv");
    ASSERT_EQ(rows.size(), 12u);
    auto verdict = [&](const std::string& who) { return rows[who].substr(0, rows[who].find('|')); };
    auto rest = [&](const std::string& who) { return rows[who].substr(rows[who].find('|') + 1); };
    EXPECT_EQ(verdict("right"), "100,pass,1.0000,inf");
    EXPECT_EQ(verdict("zipped"), "100,pass,1.0000,inf");
    EXPECT_EQ(verdict("weights").substr(0, 9), "100,pass,");  // 0.52 + 0.48 x instead of 0.5 + 0.5 x
    EXPECT_EQ(verdict("shifted").substr(0, 8), "91,look,");  // one pixel off at 128x128
    EXPECT_EQ(verdict("painted").substr(0, 8), "7,wrong,");   // right at the defaults, wrong elsewhere
    EXPECT_EQ(verdict("blank").substr(0, 8), "0,wrong,");
    EXPECT_EQ(rest("blank").substr(0, 31), "the picture is a single colour,");
    EXPECT_EQ(verdict("untinted").substr(0, 9), "66,wrong,");
    EXPECT_EQ(rest("untinted").substr(0, 34), "lacks the solution's uniform uTint");
    EXPECT_EQ(verdict("broken"), "0,error,,");
    EXPECT_NE(rest("broken").find("rings.frag:7:12: error: syntax error"), std::string::npos) << rest("broken");
    EXPECT_EQ(verdict("slow"), "0,error,,");
    // Where it stopped: the setting the worker said it was drawing (issue 29, 36).
    EXPECT_EQ(rest("slow"), "timed out at setting defaults (1 of 5)," + (cls / "slow" / "rings.glib").string() +
                                ": error: stopped after 3 s (--timeout 3) while drawing setting 1 of 5");
    {  // the time it ran before it was stopped, not 0.00 s (issue 29)
        std::istringstream csv(readAll(out / "grades.csv"));
        std::string line;
        while (std::getline(csv, line) && line.rfind("slow,", 0) != 0) {}
        std::vector<std::string> cells;
        for (size_t at = 0, comma; cells.size() < 6; at = comma + 1) {
            comma = line.find(',', at);
            cells.push_back(line.substr(at, comma - at));
        }
        EXPECT_GE(std::stod(cells[5]), 3.0) << line;
    }
    EXPECT_EQ(rest("empty"), "no script," + (cls / "empty").string() +
                                 ": error: no .glib script in this submission; it holds notes.txt");
    // Two scripts, one named like the solution's: that one is graded, and the
    // row says so (issue 37).
    EXPECT_EQ(verdict("twice"), "100,pass,1.0000,inf");
    EXPECT_EQ(rest("twice"), "\"2 .glib scripts (old.glib, rings.glib): graded rings.glib, named like the solution's\",");  // quoted: a comma
    EXPECT_EQ(rest("evil"), "the zip was refused," + (cls / "evil.zip").string() +
                                ": error: entry '../escaped.txt' leaves its folder (..); nothing unpacked");
    // The page: self-contained, the ones needing a look first, the thresholds stated.
    std::string page = readAll(out / "report.html");
    EXPECT_EQ(page.find("src=\"pictures/"), std::string::npos);
    EXPECT_GE(countOf(page, "src=\"data:image/png;base64,"), 7 * 3);
    EXPECT_NE(page.find("pass: SSIM ≥ 0.95 and PSNR ≥ 30 dB at every setting; look: SSIM ≥ 0.7 at the worst and "
                        "PSNR ≥ 18 dB at every setting; score: 100 × the worst SSIM"), std::string::npos);
    EXPECT_NE(page.find("compared at 5 settings: defaults · uFreq=2 · uFreq=12 · uTint=0 · uTint=1"), std::string::npos);
    EXPECT_LT(page.find("<b>broken</b>"), page.find("<b>painted</b>"));
    EXPECT_LT(page.find("<b>painted</b>"), page.find("<b>shifted</b>"));
    EXPECT_LT(page.find("<b>shifted</b>"), page.find("<b>right</b>"));
    EXPECT_NE(page.find("    float r = = length(vST - vec2(0.5));"), std::string::npos);  // the source line
    // Painted for the defaults: right there, wrong at the sliders' ends.
    const size_t painted = page.find("<b>painted</b>");
    const std::string paintedRow = page.substr(painted, page.find("</tr>", painted) - painted);
    EXPECT_NE(paintedRow.find("SSIM by setting: defaults 1.000 · uFreq=2 0."), std::string::npos) << paintedRow;
}

TEST(CliGrade, ResumeGradesOnlyWhatIsMissingAndEndsWithTheSameGrades) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", out = dir.path() / "out";
    const std::string frag = readAll(kSolution / "rings.frag");
    for (const char* who : {"ann", "bea", "cem", "dov"}) student(cls / who, frag);
    student(cls / "eli", replaced(frag, "6.2831853 * uFreq", "6.2831853 * 6.0"));
    auto first = runGlimmer(gradeArgs(cls, out), 120);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    auto before = csvRows(out / "grades.csv");
    ASSERT_EQ(before.size(), 5u);
    // As a kill leaves it: two whole records and half of a third, no page.
    std::istringstream records(readAll(out / "grades.jsonl"));
    std::string a, b, c;
    std::getline(records, a);
    std::getline(records, b);
    std::getline(records, c);
    std::ofstream(out / "grades.jsonl", std::ios::trunc) << a << "\n" << b << "\n" << c.substr(0, c.size() / 2);
    fs::remove(out / "report.html");
    fs::remove(out / "grades.csv");
    auto resumed = runGlimmer([&] { auto v = gradeArgs(cls, out); v.push_back("--resume"); return v; }(), 120);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_EQ(countOf(resumed.err, "batch: 3/3 graded"), 1) << resumed.err;  // only the three missing
    EXPECT_EQ(countOf(resumed.err, "batch: 4/"), 0) << resumed.err;
    EXPECT_EQ(csvRows(out / "grades.csv"), before);
    EXPECT_EQ(countOf(readAll(out / "report.html"), "<tr class="), 5);
    // Resuming with other settings would mix two gradings: refused.
    auto other = gradeArgs(cls, out);
    other.insert(other.end(), {"--resume", "--vary", "uFreq=3"});
    auto mixed = runGlimmer(other, 120);
    EXPECT_EQ(mixed.exitCode, 2);
    EXPECT_EQ(mixed.err, "glimmer: error: --resume: " + out.string() +
                             " was graded with another solution, settings, thresholds or sandbox; grade it again "
                             "without --resume, or into another -o\n");
}

// Issue 26: resuming is sound only for the same grading. Another solution
// (the same rings, copied to another folder), other thresholds or the
// sandbox turned off would mix two gradings in one report: each is refused
// before anything is graded, and the folder is left as it was.
TEST(CliGrade, ResumeWithAnotherSolutionThresholdsOrSandboxIsRefused) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", out = dir.path() / "out", other = dir.path() / "other";
    student(cls / "ann", readAll(kSolution / "rings.frag"));
    auto first = runGlimmer(gradeArgs(cls, out), 120);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    fs::create_directories(other);
    for (const char* f : {"rings.glib", "rings.frag", "st.vert"}) fs::copy_file(kSolution / f, other / f);
    const std::string header = readAll(out / "grading.txt"), records = readAll(out / "grades.jsonl");
    ASSERT_NE(records.find("\"student\":\"ann\""), std::string::npos) << records;
    auto resume = [&](const std::vector<std::string>& extra) {
        auto v = gradeArgs(cls, out);
        v.push_back("--resume");
        v.insert(v.end(), extra.begin(), extra.end());
        return v;
    };
    auto anotherSolution = resume({});
    ASSERT_EQ(anotherSolution[2], "--reference");
    anotherSolution[3] = (other / "rings.glib").string();
    const std::string refused = "glimmer: error: --resume: " + out.string() +
                                " was graded with another solution, settings, thresholds or sandbox; grade it "
                                "again without --resume, or into another -o\n";
    const std::string noSandbox = "glimmer: warning: --no-sandbox: submissions may read any file this user can read\n";
    for (const auto& [args, said] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {anotherSolution, refused},
             {resume({"--pass-ssim", "0.9"}), refused},
             {resume({"--pass-psnr", "25"}), refused},
             {resume({"--look-ssim", "0.5"}), refused},
             {resume({"--look-psnr", "25"}), refused},
             {resume({"--no-sandbox"}), noSandbox + refused}}) {
        auto r = runGlimmer(args, 120);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(r.err, said);
        EXPECT_EQ(readAll(out / "grading.txt"), header);
        EXPECT_EQ(readAll(out / "grades.jsonl"), records);
    }
}

int lineCount(const fs::path& file) {
    int n = 0;
    for (char c : readAll(file)) n += c == '\n';
    return n;
}

// The real thing: glimmer killed (SIGKILL, no chance to tidy up) after two
// results, then --resume.
TEST(CliGrade, AKilledRunResumedGradesTheRestAndEndsWithTheGradesOfOneRun) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", out = dir.path() / "out";
    const std::string frag = readAll(kSolution / "rings.frag");
    for (int k = 0; k < 8; ++k)
        student(cls / ("s" + std::to_string(k)), k % 3 ? frag : replaced(frag, "6.2831853 * uFreq", "6.2831853 * 6.0"));
    auto args = gradeArgs(cls, out);
    args[7] = "256x256";  // --size: slow enough to be killed halfway
    args.back() = "1";    // --jobs
    std::vector<std::string> full = {GLIMMER_BIN};
    full.insert(full.end(), args.begin(), args.end());
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        std::vector<char*> argv;
        for (auto& a : full) argv.push_back(a.data());
        argv.push_back(nullptr);
        std::freopen("/dev/null", "w", stderr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    auto start = std::chrono::steady_clock::now();
    while (lineCount(out / "grades.jsonl") < 2 && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));  // killed, not finished
    const int kept = lineCount(out / "grades.jsonl");
    ASSERT_GE(kept, 2);
    ASSERT_LT(kept, 8);
    args.push_back("--resume");
    auto resumed = runGlimmer(args, 120);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    const std::string rest = std::to_string(8 - kept);
    EXPECT_EQ(countOf(resumed.err, "batch: " + rest + "/" + rest + " graded"), 1) << resumed.err;
    args.pop_back();
    args[5] = (dir.path() / "once").string();  // -o
    auto once = runGlimmer(args, 120);
    ASSERT_EQ(once.exitCode, 0) << once.err;
    EXPECT_EQ(csvRows(out / "grades.csv"), csvRows(dir.path() / "once" / "grades.csv"));
    EXPECT_EQ(lineCount(out / "grades.jsonl"), 8);
}

// A submission asking for more memory than --max-memory costs only itself.
TEST(CliGrade, ASubmissionThatWouldExhaustMemoryCostsOnlyItself) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    const std::string frag = readAll(kSolution / "rings.frag");
    student(cls / "hog", frag, replaced(readAll(kSolution / "rings.glib"), "Vertex st.vert",
                                        "Texture2D 6 8192 8192 RGBA32F\nVertex st.vert"));
    student(cls / "right", frag);
    auto args = gradeArgs(cls, dir.path() / "out");
    args.insert(args.end(), {"--max-memory", "64"});
    auto r = runGlimmer(args, 120);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    auto rows = csvRows(dir.path() / "out" / "grades.csv");
    EXPECT_EQ(rows["right"].substr(0, 9), "100,pass,");
    EXPECT_EQ(rows["hog"].substr(0, rows["hog"].find(',', rows["hog"].find('|'))), "0,error,,|does not render");
    EXPECT_NE(rows["hog"].find("more than the memory budget of 64 MiB (--max-memory)"), std::string::npos) << rows["hog"];
}

// The assignment's range is the solution's: a student's narrower slider is
// still set to the solution's ends (with --set's rules it would be refused
// and the picture drawn at the student's default instead).
TEST(CliGrade, ASliderNarrowerThanTheSolutionsIsSetToTheSolutionsEnds) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    student(cls / "narrow", readAll(kSolution / "rings.frag"),
            replaced(readAll(kSolution / "rings.glib"), "uTint <0. 0.5 1.>", "uTint <0.25 0.5 0.75>"));
    // Another default: said in the row too, whatever the pictures (issue 29).
    student(cls / "otherdefault", readAll(kSolution / "rings.frag"),
            replaced(readAll(kSolution / "rings.glib"), "uFreq <2. 6. 12.>", "uFreq <2. 5. 12.>"));
    fs::create_directories(cls / "results");  // -o inside the class, left from an earlier run: not a student
    auto r = runGlimmer(gradeArgs(cls, cls / "results"), 120);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    auto rows = csvRows(cls / "results" / "grades.csv");
    EXPECT_EQ(rows.size(), 2u);
    // Graded at the solution's values, and the narrower range said (issue 29).
    EXPECT_EQ(rows["narrow"], "100,pass,1.0000,inf|uTint: range <0.25 0.75> (the solution's <0 1>),");
    // (At "defaults" each script is drawn at its own defaults: another one is wrong there.)
    EXPECT_NE(rows["otherdefault"].find("; uFreq: default 5 (the solution's 6)"), std::string::npos) << rows["otherdefault"];
    auto args = gradeArgs(cls, dir.path() / "typo");
    args.insert(args.end(), {"--vary", "uFrek=1,2"});
    auto typo = runGlimmer(args, 120);
    EXPECT_EQ(typo.exitCode, 2);
    EXPECT_EQ(typo.err, "glimmer: error: --vary uFrek: the solution " + (kSolution / "rings.glib").string() +
                            " has no uniform of that name\n");
}

// Alike on the whole, wrong in a place (issue 29): a 6x6 patch 0.3 brighter
// in a corner of a 128x128 picture (0.2% of it) keeps SSIM and PSNR at a pass;
// the local measures make it "look", said with where, and the right one
// still passes.
TEST(CliGrade, ALocalErrorIsLookedAtNotPassed) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    const std::string frag = readAll(kSolution / "rings.frag");
    student(cls / "right", frag);
    student(cls / "patch", replaced(frag, "    gl_FragColor = vec4(mix(cool, warm, ring) * (0.5 + 0.5 * uTint), 1.0);",
                                    "    gl_FragColor = vec4(mix(cool, warm, ring) * (0.5 + 0.5 * uTint), 1.0);\n"
                                    "    if (vST.s < 0.05 && vST.t < 0.05) gl_FragColor.rgb += 0.3;"));
    auto r = runGlimmer(gradeArgs(cls, dir.path() / "out"), 120);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    auto rows = csvRows(dir.path() / "out" / "grades.csv");
    EXPECT_EQ(rows["right"], "100,pass,1.0000,inf|,");
    EXPECT_EQ(rows["patch"].substr(rows["patch"].find(','), 6), ",look,") << rows["patch"];
    EXPECT_NE(rows["patch"].find("a local error: 0.22% of the pixels off by more than 24 levels, the worst 32x32 tile "
                                 "at SSIM"), std::string::npos) << rows["patch"];
}

// Without --timeout, grading has a time limit of its own, scaled to the
// solution's time on this machine in this run (issue 29), and says how it
// was chosen; a runaway submission is stopped by it. Two settings (--vary:
// the defaults and one more), so the limit is its floor: 10 s each, and
// 10 s for preparing.
TEST(CliGrade, ATimeLimitIsOnByDefaultAndSaysHowItWasChosen) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    const std::string frag = readAll(kSolution / "rings.frag");
    std::string body;
    for (int k = 0; k < 40; ++k) body += "        a = sin(a * 1.0001 + float(i) * 1e-5 + vST.s + " + std::to_string(k) + ".0);\n";
    student(cls / "slow", replaced(frag, "    gl_FragColor = ", "    float a = r;\n    for (int i = 0; i < 600000; ++i) {\n" +
                                                                 body + "    }\n    gl_FragColor = vec4(a) + "));
    std::vector<std::string> args = {"batch", cls.string(), "--reference", (kSolution / "rings.glib").string(), "-o",
                                     (dir.path() / "out").string(), "--size", "128x128", "--backend", "osmesa",
                                     "--vary", "uFreq=6"};
    auto r = runGlimmer(args, 120);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("glimmer: grading: each submission may take 30 s: per setting the larger of 10 s and 20 x "
                         "the solution's own time there (10, 10 s), and the same for preparing (10 s), each setting "
                         "stopped once it runs past its share and the earlier ones' (not one limit for the whole); "
                         "--timeout sets another"),
              std::string::npos) << r.err;
    auto rows = csvRows(dir.path() / "out" / "grades.csv");
    EXPECT_EQ(rows["slow"].substr(0, rows["slow"].find(',', rows["slow"].find('|'))),
              "0,error,,|timed out at setting defaults (1 of 2)");
    // The stop names the limit it was stopped by: no --timeout was given; and
    // it came at the first setting's deadline (preparing and that setting:
    // 20 s), not at the whole submission's 30.
    EXPECT_NE(rows["slow"].find(": error: stopped after 20 s (the time limit of grading; --timeout sets another)"),
              std::string::npos) << rows["slow"];
}

// Issue 29: a report a teacher can act on and hand back. Every row links
// its pictures full size and the student's feedback page (every setting,
// theirs beside the solution's and the difference, the messages, the
// teacher's comment); --overrides sets a score and a comment that the
// report, the CSV and the page take; --only regrades one student into the
// graded folder and leaves every other record as it was.
TEST(CliGrade, FeedbackPagesOverridesAndRegradingOneStudent) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", out = dir.path() / "out";
    const std::string frag = readAll(kSolution / "rings.frag");
    student(cls / "right", frag);
    student(cls / "painted", replaced(frag, "6.2831853 * uFreq", "6.2831853 * 6.0"));
    std::ofstream(dir.path() / "overrides.csv") << "student,score,comment\npainted,55,\"the rings are right <b>at 6</b>\"\n"
                                                   "nobody,1,\n";
    auto args = gradeArgs(cls, out);
    args.insert(args.end(), {"--overrides", (dir.path() / "overrides.csv").string()});
    auto r = runGlimmer(args, 120);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "glimmer: warning: --overrides names 'nobody', whom no row has"), 1) << r.err;
    EXPECT_EQ(csvColumn(out / "grades.csv", "score")["painted"], "55");
    EXPECT_EQ(csvColumn(out / "grades.csv", "computed_score")["painted"], "7");
    EXPECT_EQ(csvColumn(out / "grades.csv", "comment")["painted"], "the rings are right <b>at 6</b>");
    EXPECT_EQ(csvColumn(out / "grades.csv", "submission")["right"], (cls / "right").string());
    const std::string report = readAll(out / "report.html");
    EXPECT_NE(report.find("<a href=\"feedback/painted.html\">feedback page</a>"), std::string::npos);
    EXPECT_NE(report.find("<a href=\"pictures/painted-"), std::string::npos);  // the thumbnail, full size on click
    EXPECT_NE(report.find("Teacher: the rings are right &lt;b&gt;at 6&lt;/b&gt;"), std::string::npos);
    const std::string page = readAll(out / "feedback" / "painted.html");
    EXPECT_NE(page.find("Your teacher: the rings are right &lt;b&gt;at 6&lt;/b&gt;"), std::string::npos);
    EXPECT_NE(page.find("score 55 (set by your teacher; computed 7)"), std::string::npos);
    EXPECT_EQ(countOf(page, "<h3>"), 5);  // the five settings
    EXPECT_EQ(countOf(page, "<img src=\"data:image/png;base64,"), 15);  // yours, the solution's, the difference, each
    EXPECT_TRUE(fs::exists(out / "feedback" / "right.html"));

    // The student fixes the shader; only they are graded again.
    const std::string rightRecord = [&] {
        std::istringstream in(readAll(out / "grades.jsonl"));
        for (std::string line; std::getline(in, line);)
            if (line.find("\"student\":\"right\"") != std::string::npos) return line;
        return std::string();
    }();
    student(cls / "painted2", frag);
    fs::remove_all(cls / "painted");
    fs::rename(cls / "painted2", cls / "painted");
    // A student not regraded keeps their feedback page as it was: it is not made again (every
    // setting's pictures encoded full size; glimmer serve regrades one student at a time, issue 41).
    const fs::path rightPage = out / "feedback" / "right.html";
    const auto longAgo = fs::file_time_type::clock::now() - std::chrono::hours(24);
    fs::last_write_time(rightPage, longAgo);
    auto again = gradeArgs(cls, out);
    again.insert(again.end(), {"--only", "painted"});
    auto r2 = runGlimmer(again, 120);
    EXPECT_EQ(r2.exitCode, 0) << r2.err;
    EXPECT_EQ(countOf(r2.err, "batch: 1/1 graded"), 1) << r2.err;
    EXPECT_EQ(csvRows(out / "grades.csv")["painted"], "100,pass,1.0000,inf|,");
    EXPECT_NE(readAll(out / "grades.jsonl").find(rightRecord), std::string::npos);  // untouched
    EXPECT_EQ(fs::last_write_time(rightPage), longAgo);
    // Unless the teacher's override for them came, or went, since.
    std::ofstream(dir.path() / "note.csv") << "student,score,comment\nright,90,well done\n";
    auto noted = again;
    noted.insert(noted.end(), {"--overrides", (dir.path() / "note.csv").string()});
    EXPECT_EQ(runGlimmer(noted, 120).exitCode, 0);
    EXPECT_NE(readAll(rightPage).find("Your teacher: well done"), std::string::npos);
    EXPECT_NE(readAll(rightPage).find("score 90 (set by your teacher; computed 100)"), std::string::npos);
    EXPECT_EQ(runGlimmer(again, 120).exitCode, 0);
    EXPECT_EQ(readAll(rightPage).find("Your teacher:"), std::string::npos);
    EXPECT_NE(readAll(rightPage).find("score 100"), std::string::npos);
    auto typo = gradeArgs(cls, out);
    typo.insert(typo.end(), {"--only", "paintd"});
    auto r3 = runGlimmer(typo, 60);
    EXPECT_EQ(r3.exitCode, 2);
    EXPECT_EQ(r3.err, "glimmer: error: --only paintd: no such student in this class (as the report names them)\n");
}

TEST(CliGrade, TheSandboxIsOnUnlessTurnedOffAndThenSaidOnce) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    std::ofstream(dir.path() / "outside.frag") << readAll(kSolution / "rings.frag");
    student(cls / "reacher", "", replaced(readAll(kSolution / "rings.glib"), "Fragment rings.frag", "Fragment ../../outside.frag"));
    student(cls / "plain", readAll(kSolution / "rings.frag"));
    // The sandbox is the submission's folder: a script deeper inside may read the files above it there.
    student(cls / "nested" / "hw3", "", replaced(readAll(kSolution / "rings.glib"), "Fragment rings.frag", "Fragment ../rings.frag"));
    fs::rename(cls / "nested" / "hw3" / "rings.frag", cls / "nested" / "rings.frag");
    std::ofstream(cls / "nested" / "rings.frag") << readAll(kSolution / "rings.frag");
    auto boxed = runGlimmer(gradeArgs(cls, dir.path() / "boxed"), 120);
    EXPECT_EQ(boxed.exitCode, 1) << boxed.err;
    auto rows = csvRows(dir.path() / "boxed" / "grades.csv");
    EXPECT_EQ(rows["nested"].substr(0, 9), "100,pass,") << rows["nested"];
    EXPECT_EQ(rows["reacher"].substr(0, rows["reacher"].find(',', rows["reacher"].find('|'))), "0,error,,|reads files outside its folder");
    EXPECT_NE(rows["reacher"].find("is outside the sandbox"), std::string::npos) << rows["reacher"];
    auto args = gradeArgs(cls, dir.path() / "open");
    args.push_back("--no-sandbox");
    auto open = runGlimmer(args, 120);
    EXPECT_EQ(open.exitCode, 0) << open.err;
    EXPECT_EQ(countOf(open.err, "glimmer: warning: --no-sandbox: submissions may read any file this user can read\n"), 1)
        << open.err;
    EXPECT_EQ(csvRows(dir.path() / "open" / "grades.csv")["reacher"].substr(0, 9), "100,pass,");
}

TEST(CliGrade, ShardsMergeIntoTheOneReportOfALocalRun) {
    TempDir dir;
    const fs::path cls = dir.path() / "class";
    const std::string frag = readAll(kSolution / "rings.frag");
    for (const char* who : {"ann", "bea", "cem"}) student(cls / who, frag);
    student(cls / "dov", replaced(frag, "6.2831853 * uFreq", "6.2831853 * 6.0"));
    student(cls / "eli", replaced(frag, "float r = ", "float r = = "));
    auto local = runGlimmer(gradeArgs(cls, dir.path() / "local"), 120);
    ASSERT_EQ(local.exitCode, 1) << local.err;
    for (const char* s : {"1/2", "2/2"}) {
        auto args = gradeArgs(cls, dir.path() / (std::string("shard") + s[0]));
        args.insert(args.end(), {"--shard", s});
        auto r = runGlimmer(args, 120);
        ASSERT_NE(r.exitCode, 2) << r.err;
    }
    auto merged = runGlimmer({"batch-merge", (dir.path() / "shard1").string(), (dir.path() / "shard2").string(), "-o",
                              (dir.path() / "merged").string()});
    ASSERT_EQ(merged.exitCode, 0) << merged.err;
    EXPECT_EQ(countOf(merged.err, "(5 submissions from 2 shards, each exactly once)"), 1) << merged.err;
    EXPECT_EQ(csvRows(dir.path() / "merged" / "grades.csv"), csvRows(dir.path() / "local" / "grades.csv"));
    EXPECT_EQ(countOf(readAll(dir.path() / "merged" / "report.html"), "src=\"data:image/png;base64,"),
              countOf(readAll(dir.path() / "local" / "report.html"), "src=\"data:image/png;base64,"));
    auto twice = runGlimmer({"batch-merge", (dir.path() / "shard1").string(), (dir.path() / "shard1").string(), "-o",
                             (dir.path() / "bad").string()});
    EXPECT_EQ(twice.exitCode, 1);
    EXPECT_EQ(twice.err, "glimmer: error: batch-merge: ann: graded by 2 shards\n"
                         "glimmer: error: batch-merge: bea: in no shard's results\n"
                         "glimmer: error: batch-merge: cem: graded by 2 shards\n"
                         "glimmer: error: batch-merge: dov: in no shard's results\n"
                         "glimmer: error: batch-merge: eli: graded by 2 shards\n");
}

// Real names (issue 29): Jürgen and Jörgen stay two students with their
// letters (they were both J__rgen_Gro__, one silently -2), 李雷 is not
// 'script', and a folder and a zip of one student are both graded and said.
TEST(CliGrade, NamesKeepTheirLettersAndATwiceHandedInStudentIsSaid) {
    TempDir dir;
    const fs::path cls = dir.path() / "class", out = dir.path() / "out";
    const std::string frag = readAll(kSolution / "rings.frag");
    for (const char* name : {"J\xc3\xbcrgen Gro\xc3\x9f", "J\xc3\xb6rgen Gro\xc3\x9f", "\xe6\x9d\x8e\xe9\x9b\xb7", "ann"})
        student(cls / name, frag);
    zipFolder(cls / "ann.zip", {{"st.vert", readAll(kSolution / "st.vert")}, {"rings.frag", frag},
                                {"rings.glib", readAll(kSolution / "rings.glib")}});
    auto r = runGlimmer(gradeArgs(cls, out), 120);
    ASSERT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("glimmer: warning: ann handed in more than once (" + (cls / "ann").string() + ", " +
                         (cls / "ann.zip").string() + "); each is graded, as a row of its own\n"),
              std::string::npos) << r.err;
    auto rows = csvRows(out / "grades.csv");
    std::vector<std::string> students;
    for (const auto& [who, row] : rows) students.push_back(who);
    // As written, the space too (issue 37: they were Jürgen_Groß).
    EXPECT_EQ(students, (std::vector<std::string>{"J\xc3\xb6rgen Gro\xc3\x9f", "J\xc3\xbcrgen Gro\xc3\x9f", "ann",
                                                  "ann-2", "\xe6\x9d\x8e\xe9\x9b\xb7"}));
    for (const auto& [who, row] : rows) EXPECT_EQ(row.substr(0, 9), "100,pass,") << who;
    // And said in both rows, where the teacher reads (the generated class: two plain passes).
    for (const char* who : {"ann", "ann-2"})
        EXPECT_EQ(rows[who].substr(rows[who].find('|') + 1),
                  "\"handed in more than once (ann, ann.zip); each is a row of its own\",") << who;
    EXPECT_EQ(rows["\xe6\x9d\x8e\xe9\x9b\xb7"].substr(rows["\xe6\x9d\x8e\xe9\x9b\xb7"].find('|') + 1), ",");
}

TEST(CliGrade, FoldersAreGradedOnlyAgainstASolution) {
    TempDir dir;
    student(dir.path() / "class" / "ann", readAll(kSolution / "rings.frag"));
    auto r = runGlimmer({"batch", (dir.path() / "class").string(), "-o", dir.file("out")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "glimmer: error: batch: " + (dir.path() / "class").string() +
                         " is a folder or zip: submissions are graded; give --reference SOLUTION.glib\n");
    auto resume = runGlimmer({"batch", "x.glib", "--resume", "-o", dir.file("out")});
    EXPECT_EQ(resume.exitCode, 2);
    EXPECT_EQ(resume.err, "glimmer: error: batch: --vary, --no-sandbox and --resume are for grading; give --reference "
                          "SOLUTION.glib\n");
    auto strict = runGlimmer({"batch", (dir.path() / "class").string(), "--reference", (kSolution / "rings.glib").string(),
                              "--strict", "-o", dir.file("out")});
    EXPECT_EQ(strict.exitCode, 2);
    EXPECT_EQ(strict.err, "glimmer: error: batch --reference writes its own grades.jsonl and report.html in -o; "
                          "--report and --strict are for plain batch\n");
}

}  // namespace
