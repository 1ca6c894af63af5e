// Grading hand-ins as they arrive, with the engine `glimmer batch
// --reference` is: the server runs that very command (this executable, its
// sandbox and limits) on a class folder it keeps, so a hand-in gets the
// verdict grading the same files from the command line gives, and the
// graded folder is the one `batch --reference` writes (grades.csv,
// report.html, feedback/), ready to export.
//
// One thread, one batch run at a time (batch locks its output folder): each
// run takes the queued hand-ins, at most one per student, writes each
// student's folder (the lesson with their files as of the hand-in), and
// regrades just them (--only) into the class's graded folder. A hand-in cut
// off by a restart is graded again (ClassStore::takeQueued).
#pragma once
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "serve/class_store.h"
#include "serve/lesson_folder.h"

namespace glimmer {

struct GraderSettings {
    std::string glimmer;                 // the executable (this one: /proc/self/exe)
    std::string solution;                // SOLUTION.glib
    std::string stateDir;                // grading/class, grading/graded, feedback/ are under it
    std::vector<std::string> batchArgs;  // more of batch's options (--jobs, --max-memory, --overrides ...)
    double runLimitSeconds = 900;        // a whole run, on top of batch's own per-student limits
    int perRun = 48;                     // hand-ins graded in one run at most
};

class HandInGrader {
public:
    HandInGrader(ClassStore& store, const LessonFolder& lesson, GraderSettings settings);
    ~HandInGrader();
    void start();
    void wake();  // a hand-in was queued
    void stop();

    // The graded folder (grades.csv, report.html, feedback/): the export.
    std::string gradedDir() const;
    // The feedback page kept for one hand-in ("" when it has none).
    std::string feedbackFile(std::int64_t handIn) const;

    // One run over what is queued now; the number of hand-ins it finished.
    int gradeQueued();

private:
    void loop();
    ClassStore& store_;
    const LessonFolder& lesson_;
    GraderSettings settings_;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wakeup_;
    bool woken_ = false;
    std::atomic<bool> stopping_{false};
};

// Runs `argv` with stdout and stderr into `logFile`; its exit status, or -1
// when it could not start or ran past `limitSeconds` (then killed, with its
// process group). `stopping` set also kills it.
int runLogged(const std::vector<std::string>& argv, const std::string& logFile, double limitSeconds,
              const std::atomic<bool>& stopping);

}  // namespace glimmer
