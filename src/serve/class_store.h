// What `glimmer serve` keeps (issue 41): the class, every version a student
// saved, every hand-in and its grade, in one SQLite database (Debian's
// libsqlite3). No HTTP here and no GL: the routes (serve_routes.cpp) and the
// grader (hand_in_grader.cpp) call these.
//
// Contract:
//   - Durable before acknowledged: each call that changes the class commits
//     (WAL, synchronous=FULL) before it returns, so a save or hand-in whose
//     answer reached the browser survives a kill -9 of the server at any
//     moment after (tests/serve/serve_kill_test.py).
//   - Every version kept: a save stores the files it changed (a delta); the
//     files as of any version are the lesson's with every delta up to it.
//   - Thread-safe: one connection behind a mutex (a lab's load is a few
//     hundred small transactions a second at most; PERFORMANCE.md).
//   - The store holds texts the server already bounded and checked
//     (serve_limits.h); it trusts no name for a file: a student's folder
//     name is made here from their name (folderNameFor).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

struct sqlite3;

namespace glimmer {

struct Student {
    std::int64_t id = 0;
    std::string name;    // as the roster or the student gave it
    std::string folder;  // the name grading knows them by: [A-Za-z0-9._-], unique
    std::string token;   // their secret link's token
};

struct HandIn {
    std::int64_t id = 0;
    std::int64_t student = 0;
    std::int64_t version = 0;   // the files handed in: as of this version
    double at = 0;              // seconds since the epoch
    std::string state;          // queued, grading, graded, failed
    std::string verdict;        // pass, look, wrong, error (grade/grading.h); "" until graded
    int score = 0;
    std::string notes;          // the verdict's why, or why grading failed
};

// What the teacher's grid shows of one student.
struct StudentSummary {
    Student student;
    std::int64_t versions = 0;
    double lastSave = 0;        // 0: never saved
    std::string status;         // the page's verdict line at the last save ("" none)
    std::optional<HandIn> lastHandIn;
    int handIns = 0;
    bool hasThumbnail = false;
};

using FileTexts = std::map<std::string, std::string>;  // relative path -> text

class ClassStore {
public:
    // Opens (creating) the database at `path`; false with `error` otherwise.
    bool open(const std::string& path, std::string& error);
    ~ClassStore();

    // The class's secrets, made once and kept: the teacher's token and the
    // class code students join with when there is no roster.
    std::string teacherToken();
    std::string classCode();

    // A student by name: the one there is, or a new one (roster: `create`
    // true). nullopt when `create` is false and no student has the name.
    std::optional<Student> studentNamed(const std::string& name, bool create);
    std::optional<Student> studentByToken(const std::string& token);
    std::optional<Student> studentById(std::int64_t id);
    std::vector<Student> students();

    // Saves `changed` (only files that differ from what the student has now
    // are kept) with the page's status line; the version the student is at
    // after it (unchanged when nothing differed).
    std::int64_t save(std::int64_t student, const FileTexts& changed, const std::string& status);
    // The student's files as of `version` (0: the newest), the deltas merged.
    FileTexts filesAt(std::int64_t student, std::int64_t version = 0);
    std::int64_t latestVersion(std::int64_t student);

    std::int64_t handIn(std::int64_t student);  // of the newest version; its id
    std::vector<HandIn> handIns(std::int64_t student);
    std::optional<HandIn> handInById(std::int64_t id);
    // Hand-ins to grade, oldest first (queued, or cut off mid-grading by a
    // restart), at most `limit`; each is marked grading.
    std::vector<HandIn> takeQueued(int limit);
    void finishHandIn(std::int64_t id, const std::string& state, const std::string& verdict, int score,
                      const std::string& notes);

    void setThumbnail(std::int64_t student, const std::string& png);
    std::string thumbnail(std::int64_t student);

    // "Follow me": the newest slider values the teacher pushed, and its id
    // (0: none yet) so a page applies each push once.
    std::int64_t follow(const std::string& sets);
    std::pair<std::int64_t, std::string> lastFollow();

    std::vector<StudentSummary> summaries();

private:
    std::string meta(const std::string& key, const std::string& made);
    sqlite3* db_ = nullptr;
    std::mutex mutex_;
};

// "Lovelace, Ada" -> "Lovelace__Ada", "Émile Zola" -> "Émile_Zola": letters
// (UTF-8 ones too), digits, '.', '-', '_' kept, anything else '_', about 60
// bytes at most, never starting with '_' or '.', never empty: a name grading
// (`batch --reference`) reports the folder by unchanged, so --only finds it.
std::string folderNameFor(const std::string& name);

// The current time in seconds since the epoch.
double nowSeconds();

}  // namespace glimmer
