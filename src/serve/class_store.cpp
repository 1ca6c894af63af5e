#include "serve/class_store.h"

#include <sqlite3.h>

#include <chrono>
#include <set>
#include <stdexcept>

#include "serve/random_token.h"

namespace glimmer {
namespace {

// The tables. versions holds one row per save; version_files the files that
// save changed (a delta); `current` the newest text of each file a student
// changed, kept in the same transaction so a page's reload reads one row
// per file instead of merging every delta.
const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS students(id INTEGER PRIMARY KEY, name TEXT UNIQUE NOT NULL,
  folder TEXT UNIQUE NOT NULL, token TEXT UNIQUE NOT NULL, joined REAL NOT NULL);
CREATE TABLE IF NOT EXISTS versions(id INTEGER PRIMARY KEY, student INTEGER NOT NULL, at REAL NOT NULL,
  status TEXT NOT NULL);
CREATE INDEX IF NOT EXISTS versions_by_student ON versions(student, id);
CREATE TABLE IF NOT EXISTS version_files(version INTEGER NOT NULL, path TEXT NOT NULL, text TEXT NOT NULL,
  PRIMARY KEY(version, path));
CREATE TABLE IF NOT EXISTS current(student INTEGER NOT NULL, path TEXT NOT NULL, text TEXT NOT NULL,
  PRIMARY KEY(student, path));
CREATE TABLE IF NOT EXISTS handins(id INTEGER PRIMARY KEY, student INTEGER NOT NULL, version INTEGER NOT NULL,
  at REAL NOT NULL, state TEXT NOT NULL, verdict TEXT NOT NULL DEFAULT '', score INTEGER NOT NULL DEFAULT 0,
  notes TEXT NOT NULL DEFAULT '');
CREATE INDEX IF NOT EXISTS handins_by_student ON handins(student, id);
CREATE TABLE IF NOT EXISTS thumbnails(student INTEGER PRIMARY KEY, png BLOB NOT NULL, at REAL NOT NULL);
CREATE TABLE IF NOT EXISTS follows(id INTEGER PRIMARY KEY, at REAL NOT NULL, sets TEXT NOT NULL);
)sql";

// One prepared statement, finalized on every path out.
class Statement {
public:
    Statement(sqlite3* db, const char* sql) : db_(db) {
        if (sqlite3_prepare_v2(db, sql, -1, &s_, nullptr) != SQLITE_OK)
            throw std::runtime_error(std::string("the class database: ") + sqlite3_errmsg(db));
    }
    ~Statement() { sqlite3_finalize(s_); }
    Statement& bind(int i, std::int64_t v) { sqlite3_bind_int64(s_, i, v); return *this; }
    Statement& bind(int i, double v) { sqlite3_bind_double(s_, i, v); return *this; }
    Statement& bind(int i, const std::string& v) {
        sqlite3_bind_text(s_, i, v.data(), int(v.size()), SQLITE_TRANSIENT);
        return *this;
    }
    Statement& blob(int i, const std::string& v) {
        sqlite3_bind_blob(s_, i, v.data(), int(v.size()), SQLITE_TRANSIENT);
        return *this;
    }
    bool step() {  // true: a row
        const int r = sqlite3_step(s_);
        if (r == SQLITE_ROW) return true;
        if (r == SQLITE_DONE) return false;
        throw std::runtime_error(std::string("the class database: ") + sqlite3_errmsg(db_));
    }
    std::int64_t integer(int c) { return sqlite3_column_int64(s_, c); }
    double real(int c) { return sqlite3_column_double(s_, c); }
    std::string text(int c) {
        const auto* p = sqlite3_column_blob(s_, c);
        return p ? std::string(static_cast<const char*>(p), std::size_t(sqlite3_column_bytes(s_, c))) : std::string();
    }

private:
    sqlite3* db_;
    sqlite3_stmt* s_ = nullptr;
};

void exec(sqlite3* db, const char* sql) {
    char* message = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        std::string why = message ? message : "failed";
        sqlite3_free(message);
        throw std::runtime_error("the class database: " + why);
    }
}

// A transaction committed at the end of its scope, rolled back on a throw.
class Transaction {
public:
    explicit Transaction(sqlite3* db) : db_(db) { exec(db, "BEGIN IMMEDIATE"); }
    void commit() { exec(db_, "COMMIT"); done_ = true; }
    ~Transaction() { if (!done_) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr); }

private:
    sqlite3* db_;
    bool done_ = false;
};

Student studentFrom(Statement& s) {
    return Student{s.integer(0), s.text(1), s.text(2), s.text(3)};
}

HandIn handInFrom(Statement& s) {
    return HandIn{s.integer(0), s.integer(1), s.integer(2), s.real(3), s.text(4), s.text(5), int(s.integer(6)), s.text(7)};
}

const char* kHandInColumns = "SELECT id, student, version, at, state, verdict, score, notes FROM handins ";

}  // namespace

double nowSeconds() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// The length of the whole UTF-8 character at `k` that is a letter as batch
// keeps it (process/batch.cpp's names: not a C1 control), or 0.
static std::size_t utf8LetterAt(const std::string& s, std::size_t k) {
    const unsigned char c = static_cast<unsigned char>(s[k]);
    const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (n == 0 || k + n > s.size()) return 0;
    for (std::size_t i = 1; i < n; ++i)
        if ((static_cast<unsigned char>(s[k + i]) & 0xC0) != 0x80) return 0;
    if (c == 0xC2 && static_cast<unsigned char>(s[k + 1]) < 0xA0) return 0;  // U+0080..U+009F
    return n;
}

std::string folderNameFor(const std::string& name) {
    std::string out;
    for (std::size_t k = 0; k < name.size() && out.size() < 60;) {
        if (const std::size_t n = utf8LetterAt(name, k)) {
            out.append(name, k, n);
            k += n;
            continue;
        }
        const unsigned char c = static_cast<unsigned char>(name[k++]);
        const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                          c == '-' || c == '_';
        out += kept ? char(c) : '_';
    }
    // As batch names a student: never a leading '_' or '.' (it would drop them, and --only would not match).
    while (!out.empty() && (out.front() == '_' || out.front() == '.')) out.erase(0, 1);
    return out.empty() ? "student" : out;
}

bool ClassStore::open(const std::string& path, std::string& error) {
    if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        error = std::string("cannot open the class database: ") + (db_ ? sqlite3_errmsg(db_) : "out of memory");
        return false;
    }
    sqlite3_busy_timeout(db_, 5000);
    try {
        // WAL with a full sync at each commit: a commit is on disk when it returns.
        exec(db_, "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON;");
        exec(db_, kSchema);
    } catch (const std::exception& e) {
        error = e.what();
        return false;
    }
    return true;
}

ClassStore::~ClassStore() { sqlite3_close(db_); }

std::string ClassStore::meta(const std::string& key, const std::string& made) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement get(db_, "SELECT value FROM meta WHERE key = ?");
    get.bind(1, key);
    if (get.step()) return get.text(0);
    Statement put(db_, "INSERT INTO meta(key, value) VALUES(?, ?)");
    put.bind(1, key).bind(2, made).step();
    return made;
}

std::string ClassStore::teacherToken() { return meta("teacher_token", randomToken()); }
std::string ClassStore::classCode() { return meta("class_code", randomClassCode()); }

std::optional<Student> ClassStore::studentNamed(const std::string& name, bool create) {
    std::lock_guard<std::mutex> lock(mutex_);
    {
        Statement s(db_, "SELECT id, name, folder, token FROM students WHERE name = ?");
        s.bind(1, name);
        if (s.step()) return studentFrom(s);
    }
    if (!create) return std::nullopt;
    // The folder name: unique, with a number after it when two names make the same one.
    const std::string base = folderNameFor(name);
    std::string folder = base;
    for (int k = 2;; ++k) {
        Statement taken(db_, "SELECT 1 FROM students WHERE folder = ?");
        taken.bind(1, folder);
        if (!taken.step()) break;
        folder = base + "-" + std::to_string(k);
    }
    Student made{0, name, folder, randomToken()};
    Statement put(db_, "INSERT INTO students(name, folder, token, joined) VALUES(?, ?, ?, ?)");
    put.bind(1, name).bind(2, folder).bind(3, made.token).bind(4, nowSeconds()).step();
    made.id = sqlite3_last_insert_rowid(db_);
    return made;
}

std::optional<Student> ClassStore::studentByToken(const std::string& token) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "SELECT id, name, folder, token FROM students WHERE token = ?");
    s.bind(1, token);
    if (s.step()) return studentFrom(s);
    return std::nullopt;
}

std::optional<Student> ClassStore::studentById(std::int64_t id) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "SELECT id, name, folder, token FROM students WHERE id = ?");
    s.bind(1, id);
    if (s.step()) return studentFrom(s);
    return std::nullopt;
}

std::vector<Student> ClassStore::students() {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "SELECT id, name, folder, token FROM students ORDER BY name");
    std::vector<Student> out;
    while (s.step()) out.push_back(studentFrom(s));
    return out;
}

std::int64_t ClassStore::save(std::int64_t student, const FileTexts& changed, const std::string& status) {
    std::lock_guard<std::mutex> lock(mutex_);
    Transaction t(db_);
    FileTexts differing;
    for (const auto& [path, text] : changed) {
        Statement now(db_, "SELECT text FROM current WHERE student = ? AND path = ?");
        now.bind(1, student).bind(2, path);
        if (now.step() && now.text(0) == text) continue;
        differing[path] = text;
    }
    std::int64_t version = 0;
    {
        Statement last(db_, "SELECT id, status FROM versions WHERE student = ? ORDER BY id DESC LIMIT 1");
        last.bind(1, student);
        if (last.step()) {
            version = last.integer(0);
            if (differing.empty() && last.text(1) == status) return version;  // nothing new: no version
        }
    }
    Statement v(db_, "INSERT INTO versions(student, at, status) VALUES(?, ?, ?)");
    v.bind(1, student).bind(2, nowSeconds()).bind(3, status).step();
    version = sqlite3_last_insert_rowid(db_);
    for (const auto& [path, text] : differing) {
        Statement f(db_, "INSERT INTO version_files(version, path, text) VALUES(?, ?, ?)");
        f.bind(1, version).bind(2, path).bind(3, text).step();
        Statement c(db_, "INSERT INTO current(student, path, text) VALUES(?, ?, ?) "
                         "ON CONFLICT(student, path) DO UPDATE SET text = excluded.text");
        c.bind(1, student).bind(2, path).bind(3, text).step();
    }
    t.commit();
    return version;
}

FileTexts ClassStore::filesAt(std::int64_t student, std::int64_t version) {
    std::lock_guard<std::mutex> lock(mutex_);
    FileTexts out;
    if (version == 0) {
        Statement s(db_, "SELECT path, text FROM current WHERE student = ?");
        s.bind(1, student);
        while (s.step()) out[s.text(0)] = s.text(1);
        return out;
    }
    // The deltas up to `version`, oldest first: each newer text replaces the older.
    Statement s(db_, "SELECT f.path, f.text FROM version_files f JOIN versions v ON v.id = f.version "
                     "WHERE v.student = ? AND v.id <= ? ORDER BY v.id");
    s.bind(1, student).bind(2, version);
    while (s.step()) out[s.text(0)] = s.text(1);
    return out;
}

std::int64_t ClassStore::latestVersion(std::int64_t student) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "SELECT COALESCE(MAX(id), 0) FROM versions WHERE student = ?");
    s.bind(1, student);
    s.step();
    return s.integer(0);
}

std::int64_t ClassStore::handIn(std::int64_t student) {
    const std::int64_t version = latestVersion(student);
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "INSERT INTO handins(student, version, at, state) VALUES(?, ?, ?, 'queued')");
    s.bind(1, student).bind(2, version).bind(3, nowSeconds()).step();
    return sqlite3_last_insert_rowid(db_);
}

std::vector<HandIn> ClassStore::handIns(std::int64_t student) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, (std::string(kHandInColumns) + "WHERE student = ? ORDER BY id").c_str());
    s.bind(1, student);
    std::vector<HandIn> out;
    while (s.step()) out.push_back(handInFrom(s));
    return out;
}

std::optional<HandIn> ClassStore::handInById(std::int64_t id) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, (std::string(kHandInColumns) + "WHERE id = ?").c_str());
    s.bind(1, id);
    if (s.step()) return handInFrom(s);
    return std::nullopt;
}

std::vector<HandIn> ClassStore::takeQueued(int limit) {
    std::lock_guard<std::mutex> lock(mutex_);
    Transaction t(db_);
    std::vector<HandIn> out;
    std::set<std::int64_t> taken;  // one hand-in per student a run: a student's second waits for the next
    {
        Statement s(db_, (std::string(kHandInColumns) + "WHERE state IN ('queued', 'grading') ORDER BY id").c_str());
        while (s.step() && int(out.size()) < limit) {
            HandIn h = handInFrom(s);
            if (taken.insert(h.student).second) out.push_back(std::move(h));
        }
    }
    for (auto& h : out) {
        Statement u(db_, "UPDATE handins SET state = 'grading' WHERE id = ?");
        u.bind(1, h.id).step();
        h.state = "grading";
    }
    t.commit();
    return out;
}

void ClassStore::finishHandIn(std::int64_t id, const std::string& state, const std::string& verdict, int score,
                              const std::string& notes) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "UPDATE handins SET state = ?, verdict = ?, score = ?, notes = ? WHERE id = ?");
    s.bind(1, state).bind(2, verdict).bind(3, std::int64_t(score)).bind(4, notes).bind(5, id).step();
}

void ClassStore::setThumbnail(std::int64_t student, const std::string& png) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "INSERT INTO thumbnails(student, png, at) VALUES(?, ?, ?) "
                     "ON CONFLICT(student) DO UPDATE SET png = excluded.png, at = excluded.at");
    s.bind(1, student).blob(2, png).bind(3, nowSeconds()).step();
}

std::string ClassStore::thumbnail(std::int64_t student) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "SELECT png FROM thumbnails WHERE student = ?");
    s.bind(1, student);
    return s.step() ? s.text(0) : std::string();
}

std::int64_t ClassStore::follow(const std::string& sets) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "INSERT INTO follows(at, sets) VALUES(?, ?)");
    s.bind(1, nowSeconds()).bind(2, sets).step();
    return sqlite3_last_insert_rowid(db_);
}

std::pair<std::int64_t, std::string> ClassStore::lastFollow() {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement s(db_, "SELECT id, sets FROM follows ORDER BY id DESC LIMIT 1");
    if (s.step()) return {s.integer(0), s.text(1)};
    return {0, ""};
}

std::vector<StudentSummary> ClassStore::summaries() {
    std::vector<StudentSummary> out;
    for (const Student& st : students()) {
        StudentSummary sum;
        sum.student = st;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            Statement v(db_, "SELECT COUNT(*), COALESCE(MAX(at), 0) FROM versions WHERE student = ?");
            v.bind(1, st.id);
            v.step();
            sum.versions = v.integer(0);
            sum.lastSave = v.real(1);
            Statement status(db_, "SELECT status FROM versions WHERE student = ? ORDER BY id DESC LIMIT 1");
            status.bind(1, st.id);
            if (status.step()) sum.status = status.text(0);
            Statement h(db_, (std::string(kHandInColumns) + "WHERE student = ? ORDER BY id DESC").c_str());
            h.bind(1, st.id);
            while (h.step()) {
                if (!sum.lastHandIn) sum.lastHandIn = handInFrom(h);
                ++sum.handIns;
            }
            Statement t(db_, "SELECT 1 FROM thumbnails WHERE student = ?");
            t.bind(1, st.id);
            sum.hasThumbnail = t.step();
        }
        out.push_back(std::move(sum));
    }
    return out;
}

}  // namespace glimmer
