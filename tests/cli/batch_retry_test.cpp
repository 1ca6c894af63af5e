// Issue 36: a picture the machine lost is never a result. On a GPU shared
// by several workers one process can reset the others' work (they then
// read back zeros, with or without a reset reported); batch draws such a
// job again, alone in a fresh worker, and only that second drawing counts.
// llvmpipe never loses a context, so the loss is put in by the worker's test
// hook GLIMMER_TEST_FAULT (process/batch_worker.cpp).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_glimmer.h"

namespace {

namespace fs = std::filesystem;
using glimmer_cli::countOf;
using glimmer_cli::readAll;
using glimmer_cli::writeSolid;
using glimmer_cli::runGlimmer;
using glimmer_cli::TempDir;
using glimmer_cli::TestFaultEnv;


// The PNG batch wrote for the script named `stem` (batch names it after the
// whole path), or "" when there is none.
std::string pngOf(const fs::path& out, const std::string& stem) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out, ec)) {
        const std::string name = e.path().filename().string();
        if (name.size() > stem.size() + 4 && name.compare(name.size() - stem.size() - 4, std::string::npos, stem + ".png") == 0)
            return e.path().string();
    }
    return "";
}

std::vector<nlohmann::json> report(const fs::path& path) {
    std::vector<nlohmann::json> out;
    std::istringstream in(readAll(path));
    for (std::string l; std::getline(in, l);) out.push_back(nlohmann::json::parse(l, nullptr, false));
    return out;
}

TEST(CliBatchRetry, APictureLostToAResetIsDrawnAgainAloneAndKept) {
    TempDir dir;
    std::vector<std::string> scripts;
    for (int k = 0; k < 5; ++k) scripts.push_back(writeSolid(dir, k == 2 ? "lost.glib" : "s" + std::to_string(k) + ".glib", k));
    const fs::path marker = dir.path() / "fault-happened";
    std::vector<std::string> args = {"batch"};
    args.insert(args.end(), scripts.begin(), scripts.end());
    for (const std::string& a : std::vector<std::string>{"-o", dir.file("out"), "--report", dir.file("r.jsonl"), "--size",
                                                         "32x32", "--backend", "osmesa", "--jobs", "2"})
        args.push_back(a);
    TestFaultEnv fault("reset:lost.glib:" + marker.string());
    auto r = runGlimmer(args);
    EXPECT_TRUE(fs::exists(marker)) << "the fault never happened";
    EXPECT_EQ(r.exitCode, 0) << r.err;
    auto lines = report(dir.path() / "r.jsonl");
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[2].value("exit", -1), 0) << lines[2].dump();
    EXPECT_EQ(lines[2].value("diagnostics", "?"), "") << lines[2].dump();
    // The kept picture is the script's own: what `glimmer render` draws.
    auto ref = runGlimmer({"-q", "render", scripts[2], "-o", dir.file("ref.png"), "--size", "32x32", "--backend", "osmesa"});
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    ASSERT_NE(pngOf(dir.path() / "out", "_lost"), "");
    EXPECT_EQ(readAll(pngOf(dir.path() / "out", "_lost")), readAll(dir.path() / "ref.png"));
}

TEST(CliBatchRetry, AResetOnEveryDrawingIsAnErrorThatSaysSoAndWritesNoPicture) {
    TempDir dir;
    const std::string good = writeSolid(dir, "good.glib", 0), lost = writeSolid(dir, "lost.glib", 1);
    TestFaultEnv fault("reset:lost.glib:");
    auto r = runGlimmer({"batch", good, lost, "-o", dir.file("out"), "--report", dir.file("r.jsonl"), "--size", "32x32",
                         "--backend", "osmesa", "--jobs", "2"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    auto lines = report(dir.path() / "r.jsonl");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].value("exit", -1), 0) << lines[0].dump();
    EXPECT_EQ(lines[1].value("exit", -1), 1) << lines[1].dump();
    EXPECT_EQ(lines[1].value("diagnostics", ""),
              "glimmer: error: the GPU was reset by another process while this script drew (GLIMMER_TEST_FAULT)\n"
              "glimmer: note: the same when drawn again, alone on the machine in a fresh worker\n");
    EXPECT_NE(pngOf(dir.path() / "out", "_good"), "");
    EXPECT_EQ(pngOf(dir.path() / "out", "_lost"), "");
}

// A worker that never gets its context (on the H200: waiting behind a
// process stuck in NVIDIA's driver) is killed after the context's time
// limit and its job drawn alone in a fresh worker; when no worker ever gets
// one, every job says so, with what to look for, and the batch ends.
TEST(CliBatchRetry, AWorkerStuckBeforeItsContextIsReplacedAndTheBatchEnds) {
    TempDir dir;
    const std::string a = writeSolid(dir, "a.glib", 0), b = writeSolid(dir, "b.glib", 1);
    const fs::path marker = dir.path() / "fault-happened";
    auto batch = [&](const std::string& spec, const std::string& out) {
        TestFaultEnv fault(spec);
        return runGlimmer({"batch", a, b, "-o", dir.file(out), "--report", dir.file(out + ".jsonl"), "--size", "32x32",
                           "--backend", "osmesa", "--jobs", "2"},
                          60);
    };
    auto once = batch("stuck:context:" + marker.string(), "once");
    EXPECT_TRUE(fs::exists(marker)) << "the fault never happened";
    EXPECT_EQ(once.exitCode, 0) << once.err;
    auto lines = report(dir.path() / "once.jsonl");
    ASSERT_EQ(lines.size(), 2u);
    for (const auto& l : lines) EXPECT_EQ(l.value("diagnostics", "?"), "") << l.dump();
    auto ref = runGlimmer({"-q", "render", a, "-o", dir.file("a.png"), "--size", "32x32", "--backend", "osmesa"});
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    EXPECT_EQ(readAll(pngOf(dir.path() / "once", "_a")), readAll(dir.path() / "a.png"));

    auto always = batch("stuck:context:", "always");
    EXPECT_EQ(always.exitCode, 1) << always.err;
    lines = report(dir.path() / "always.jsonl");
    ASSERT_EQ(lines.size(), 2u);
    for (size_t k = 0; k < 2; ++k)
        EXPECT_EQ(lines[k].value("diagnostics", ""),
                  (k ? b : a) + ": error: the worker could not make its GL context in 2 s\n"
                  "glimmer: note: on a GPU, a process stuck in the driver (one killed while drawing, say) holds every new "
                  "context: `ps -eo pid,stat,wchan,args` shows it in state D\n"
                  "glimmer: note: the same when drawn again, alone on the machine in a fresh worker\n") << lines[k].dump();
    EXPECT_EQ(pngOf(dir.path() / "always", "_a"), "");
}

// A worker that dies while drawing (killed here, as the kernel's OOM killer
// or a driver crash would) loses only its job: that job is drawn again,
// alone, in a fresh worker, and only that second outcome counts (here the
// fresh worker dies too, so the job says the renderer crashed); the other
// script is drawn as if nothing happened, by yet another worker.
TEST(CliBatchRetry, AWorkerThatDiesWhileDrawingLosesOnlyItsJob) {
    TempDir dir, out, logs;
    const std::string runaway = glimmer_cli::writeRunawayScript(dir), solid = writeSolid(dir, "b.glib", 1);
    const pid_t parent = glimmer_cli::startGlimmer({"batch", runaway, solid, "-o", out.path().string(), "--report",
                                                    dir.file("r.jsonl"), "--size", "32x32", "--backend", "osmesa",
                                                    "--jobs", "1", "--timeout", "120"},
                                                   logs.path().string());
    // The worker drawing the runaway script, then the fresh one drawing it again.
    pid_t killed = 0;
    for (int round = 0; round < 2; ++round) {
        pid_t worker = 0;
        for (int i = 0; i < 400 && !worker; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            for (pid_t kid : glimmer_cli::childrenOf(parent))
                if (kid != killed) worker = kid;
        }
        ASSERT_NE(worker, 0) << "round " << round << ": no worker; " << readAll(logs.file("stderr"));
        std::this_thread::sleep_for(std::chrono::milliseconds(500));  // drawing by now, or still preparing
        ::kill(worker, SIGKILL);
        killed = worker;
    }
    int status = 0;
    bool ended = false;
    for (int i = 0; i < 1200 && !ended; ++i) {  // up to a minute for the other script
        ended = ::waitpid(parent, &status, WNOHANG) == parent;
        if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!ended) {
        ::kill(parent, SIGKILL);
        ::waitpid(parent, &status, 0);
    }
    ASSERT_TRUE(ended) << "the batch did not end: " << readAll(logs.file("stderr"));
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status << " " << readAll(logs.file("stderr"));
    auto lines = report(dir.path() / "r.jsonl");
    ASSERT_EQ(lines.size(), 2u) << readAll(dir.path() / "r.jsonl");
    const std::string said = lines[0].value("diagnostics", "");
    EXPECT_EQ(said.rfind(runaway + ": error: the renderer crashed while ", 0), 0u) << said;
    const std::string again = "glimmer: note: the same when drawn again, alone on the machine in a fresh worker\n";
    EXPECT_TRUE(said.size() > again.size() && said.compare(said.size() - again.size(), again.size(), again) == 0) << said;
    EXPECT_EQ(countOf(said, "\n"), 2) << said;  // the error and the note, once each
    EXPECT_EQ(lines[1].value("diagnostics", "?"), "") << lines[1].dump();
    EXPECT_EQ(lines[1].value("exit", -1), 0) << lines[1].dump();
    EXPECT_EQ(pngOf(out.path(), "_slow"), "");
    auto ref = runGlimmer({"-q", "render", solid, "-o", dir.file("b.png"), "--size", "32x32", "--backend", "osmesa"});
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    EXPECT_EQ(readAll(pngOf(out.path(), "_b")), readAll(dir.path() / "b.png"));
}

// Grading: a correct submission whose first drawing read back as zeros (an
// NVIDIA worker after another's kill, no error said) is graded on its second,
// lone drawing, not "wrong, the picture is a single colour".
TEST(CliBatchRetry, ASingleColourIsAVerdictOnlyWhenAFreshWorkerDrawsItAgain) {
    TempDir dir;
    const fs::path solution = fs::path(GLIMMER_TEST_DATA) / "grading" / "solution";
    const fs::path cls = dir.path() / "class";
    for (const char* who : {"ana", "ben", "cleo"}) {
        fs::create_directories(cls / who);
        for (const char* f : {"rings.glib", "rings.frag", "st.vert"}) fs::copy_file(solution / f, cls / who / f);
    }
    const fs::path marker = dir.path() / "fault-happened";
    auto grade = [&](const std::string& spec, const std::string& out, const char* jobs = "2") {
        TestFaultEnv fault(spec);
        return runGlimmer({"batch", cls.string(), "--reference", (solution / "rings.glib").string(), "-o",
                           (dir.path() / out).string(), "--size", "64x64", "--backend", "osmesa", "--jobs", jobs},
                          120);
    };
    auto r = grade("zeros:/ben/:" + marker.string(), "once");
    EXPECT_TRUE(fs::exists(marker)) << "the fault never happened";
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string once = readAll(dir.path() / "once" / "grades.csv");
    EXPECT_NE(once.find("\nben,100,pass,"), std::string::npos) << once;
    // A worker left broken (zeros from then on): the second drawing is in a
    // fresh worker, never the one that drew the first, even when it is the
    // only one (issue 40: a used worker 0 kept for the lone drawing).
    const fs::path brokenMarker = dir.path() / "broken-happened";
    r = grade("broken:/ben/:" + brokenMarker.string(), "broken", "1");
    EXPECT_TRUE(fs::exists(brokenMarker)) << "the fault never happened";
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string broken = readAll(dir.path() / "broken" / "grades.csv");
    EXPECT_NE(broken.find("\nben,100,pass,"), std::string::npos) << broken;
    // Zeros on every drawing: then it is the verdict, said as before.
    r = grade("zeros:/ben/:", "always");
    const std::string always = readAll(dir.path() / "always" / "grades.csv");
    EXPECT_NE(always.find("\nben,0,wrong,"), std::string::npos) << always;
    EXPECT_NE(always.find("the picture is a single colour"), std::string::npos) << always;
    EXPECT_NE(always.find("\nana,100,pass,"), std::string::npos) << always;
}

}  // namespace
