#include "serve/hand_in_grader.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <map>

#include "grade/grade_merge.h"
#include "grade/grade_row.h"
#include "util/read_file.h"
#include "util/write_file.h"

namespace fs = std::filesystem;

namespace glimmer {

int runLogged(const std::vector<std::string>& argv, const std::string& logFile, double limitSeconds,
              const std::atomic<bool>& stopping) {
    const int log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log < 0) return -1;
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) {
        ::close(log);
        return -1;
    }
    if (pid == 0) {
        setpgid(0, 0);  // its own group: a time-out kills batch and its workers together
        // The server killed (kill -9 included): batch goes too, instead of holding the graded
        // folder's lock against the restarted server (seen in serve_kill_test).
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        // Below the server in the CPU's queue: a save answered in milliseconds matters more to a
        // typing student than a grade a second sooner (tools/serve-load.py measures both).
        if (nice(10) == -1) {}
        if (getppid() != parent) _exit(127);  // the server died before the line above
        // The server blocks its stop signals and ignores SIGPIPE; batch starts as any command does.
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        signal(SIGPIPE, SIG_DFL);
        dup2(log, 1);
        dup2(log, 2);
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) dup2(null, 0);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    ::close(log);
    setpgid(pid, pid);
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
        int status = 0;
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        if (r < 0 && errno != EINTR) return -1;
        const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (spent > limitSeconds || stopping) {
            kill(-pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        usleep(50 * 1000);
    }
}

HandInGrader::HandInGrader(ClassStore& store, const LessonFolder& lesson, GraderSettings settings)
    : store_(store), lesson_(lesson), settings_(std::move(settings)) {}

HandInGrader::~HandInGrader() { stop(); }

void HandInGrader::start() { thread_ = std::thread([this] { loop(); }); }

void HandInGrader::wake() {
    std::lock_guard<std::mutex> lock(mutex_);
    woken_ = true;
    wakeup_.notify_one();
}

void HandInGrader::stop() {
    stopping_ = true;
    wake();
    if (thread_.joinable()) thread_.join();
}

std::string HandInGrader::gradedDir() const { return (fs::path(settings_.stateDir) / "grading" / "graded").string(); }

std::string HandInGrader::feedbackFile(std::int64_t handIn) const {
    const fs::path f = fs::path(settings_.stateDir) / "feedback" / fmt::format("{}.html", handIn);
    std::error_code ec;
    return fs::is_regular_file(f, ec) ? f.string() : "";
}

void HandInGrader::loop() {
    while (!stopping_) {
        // Grade until nothing is queued, then wait for a hand-in (or a second: one
        // queued while a run was finishing is never left waiting for the next).
        while (!stopping_ && gradeQueued() > 0) {}
        std::unique_lock<std::mutex> lock(mutex_);
        wakeup_.wait_for(lock, std::chrono::seconds(1), [this] { return woken_ || stopping_.load(); });
        woken_ = false;
    }
}

int HandInGrader::gradeQueued() {
    const std::vector<HandIn> queued = store_.takeQueued(settings_.perRun);
    if (queued.empty()) return 0;
    const fs::path root = fs::path(settings_.stateDir) / "grading";
    const fs::path classDir = root / "class", graded = root / "graded", feedback = fs::path(settings_.stateDir) / "feedback";
    std::error_code ec;
    fs::create_directories(classDir, ec);
    fs::create_directories(feedback, ec);
    std::map<std::int64_t, Student> who;
    std::vector<HandIn> toGrade;
    for (const HandIn& h : queued) {
        const auto student = store_.studentById(h.student);
        std::string why;
        if (!student) {
            store_.finishHandIn(h.id, "failed", "", 0, "no such student");
            continue;
        }
        if (!writeStudentFolder((classDir / student->folder).string(), lesson_, store_.filesAt(h.student, h.version),
                                why)) {
            store_.finishHandIn(h.id, "failed", "", 0, "the server could not write the hand-in: " + why);
            continue;
        }
        who[h.id] = *student;
        toGrade.push_back(h);
    }
    if (toGrade.empty()) return int(queued.size());
    std::vector<std::string> argv = {settings_.glimmer, "batch", "--reference", settings_.solution, "-o", graded.string()};
    for (const auto& a : settings_.batchArgs) argv.push_back(a);
    // Into the graded folder once one exists: only these students again, the rest kept.
    if (fs::exists(graded / "grades.jsonl", ec))
        for (const HandIn& h : toGrade) argv.push_back("--only=" + who[h.id].folder);
    argv.push_back("--");  // --only would take the class folder as one more name
    argv.push_back(classDir.string());
    const std::string logFile = (root / "last-run.log").string();
    const int exit = runLogged(argv, logFile, settings_.runLimitSeconds, stopping_);
    if (stopping_) {  // cut off by the server stopping: graded again at the next start
        for (const HandIn& h : toGrade) store_.finishHandIn(h.id, "queued", "", 0, "");
        return 0;
    }
    // The verdicts: the records batch wrote, read as --resume reads them.
    std::map<std::string, GradeRow> rows;
    std::string text, why;
    std::vector<GradeRow> records;
    if (readRegularFile((graded / "grades.jsonl").string(), std::size_t(1) << 30, text, why) &&
        parseRecords(text, (graded / "grades.jsonl").string(), records, why))
        for (GradeRow& r : records) rows[r.student] = std::move(r);
    std::string logText;
    readRegularFile(logFile, 1 << 20, logText, why);
    // Another batch holds the graded folder (one from before a restart, finishing): not the
    // students' fault; graded again in a moment.
    if (exit == 2 && logText.find("another glimmer batch is writing into this folder") != std::string::npos) {
        for (const HandIn& h : toGrade) store_.finishHandIn(h.id, "queued", "", 0, "");
        std::this_thread::sleep_for(std::chrono::seconds(1));
        return 0;
    }
    for (const HandIn& h : toGrade) {
        const Student& st = who[h.id];
        const auto row = rows.find(st.folder);
        // exit 0 or 1 (a student's error is a verdict); 2 or a kill: batch refused or never finished,
        // and a record left from an earlier hand-in is not this one's.
        if (row == rows.end() || (exit != 0 && exit != 1)) {
            // batch refused the run: its own words, so the teacher sees why; the server's folders and
            // the solution's named as relative (a student reads this too).
            std::string tail = logText.size() > 2000 ? logText.substr(logText.size() - 2000) : logText;
            for (const std::string& dir : {settings_.stateDir + "/", fs::path(settings_.solution).parent_path().string() + "/"})
                for (std::size_t at; (at = tail.find(dir)) != std::string::npos;) tail.erase(at, dir.size());
            store_.finishHandIn(h.id, "failed", "", 0, fmt::format("grading did not run (exit {}): {}", exit, tail));
            continue;
        }
        std::string page;
        const fs::path from = graded / "feedback" / (st.folder + ".html");
        if (readRegularFile(from.string(), std::size_t(64) << 20, page, why)) {
            std::string error;
            writeBytesReplacing((feedback / fmt::format("{}.html", h.id)).string(), page.data(), page.size(), error);
        }
        std::string notes = row->second.diagnostics.empty() ? row->second.notes
                                                            : row->second.notes + "\n" + row->second.diagnostics;
        // Files named as the student knows them ("blur.glib:3:1: ..."), not where the server keeps them.
        const std::string prefix = (classDir / st.folder).string() + "/";
        for (std::size_t at; (at = notes.find(prefix)) != std::string::npos;) notes.erase(at, prefix.size());
        store_.finishHandIn(h.id, "graded", row->second.verdict, row->second.score, notes);
    }
    return int(queued.size());
}

}  // namespace glimmer
