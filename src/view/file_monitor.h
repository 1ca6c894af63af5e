// Notices when files a script uses have changed, and only once their
// content has settled: editors that truncate first, or write twice, must
// not cause a reload of a half-written file or two reloads.
//
// The kernel says when to look (inotify on each file's folder, so an editor
// that saves by renaming a new file over the old one is seen too); only the
// files it names are hashed again. With nothing changing, nothing is read
// and a caller can sleep on notifyFd() until the kernel reports something.
// Where inotify is missing every file is hashed on each poll, as before.
// (Named "monitor", not "watch": a watch in Glimmer is a shader expression's
// value shown over its pass, pipeline/watch.h.)
#pragma once
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace glimmer {

class FileMonitor {
public:
    using Clock = std::chrono::steady_clock;

    // `settle`: how long a changed content must stay the same before it
    // counts. Polling every ~25 ms while busy() with 60 ms settle reloads
    // well within 200 ms of a save.
    explicit FileMonitor(std::chrono::milliseconds settle = std::chrono::milliseconds(60));
    ~FileMonitor();
    FileMonitor(const FileMonitor&) = delete;
    FileMonitor& operator=(const FileMonitor&) = delete;

    // Starts following exactly these files, taking their current content as
    // the known state.
    void follow(const std::vector<std::string>& paths);

    // Reads what the kernel reported and hashes the files it named (all
    // files without inotify). Returns the files whose content changed and has
    // stayed the same for `settle`, and takes that content as the new known
    // state; empty when nothing settled yet.
    std::vector<std::string> poll(Clock::time_point now = Clock::now());

    // True while a changed file waits to settle (or without inotify): poll
    // again in ~25 ms. False: nothing to do until notifyFd() is readable.
    bool busy() const;

    // The inotify descriptor (readable when a watched folder changed), for a
    // caller that sleeps in poll(2)/epoll; -1 without inotify. Stays the same
    // for the watch's life.
    int notifyFd() const { return fd_; }

    // How many times poll() hashed a file: a test can see an idle watch reads nothing.
    std::uint64_t hashesDone() const { return hashes_; }

    const std::vector<std::string>& paths() const { return order_; }

private:
    struct Entry {
        std::optional<std::uint64_t> known;    // hash of the content last reported (nullopt: missing)
        std::optional<std::uint64_t> pending;  // a different content seen since
        Clock::time_point pendingSince{};
        bool hasPending = false;
        bool dirty = false;  // the kernel named it since it was last hashed
        bool unwatched = false;  // its folder could not be watched: hashed on every poll
    };
    void drainEvents();
    std::chrono::milliseconds settle_;
    std::map<std::string, Entry> entries_;
    std::vector<std::string> order_;
    int fd_ = -1;
    std::map<int, std::string> dirs_;                    // watch descriptor -> folder
    std::map<std::string, std::set<std::string>> byDir_;  // folder -> watched files in it (as given)
    std::uint64_t hashes_ = 0;
};

// FNV-1a of a file's bytes; nullopt when it cannot be read.
std::optional<std::uint64_t> hashFile(const std::string& path);

}  // namespace glimmer
