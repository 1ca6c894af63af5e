#include "view/file_monitor.h"

#include <fcntl.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "util/read_file.h"

namespace glimmer {

std::optional<std::uint64_t> hashFile(const std::string& path) {
    std::string why;
    if (!checkRegularFile(path, why)) return std::nullopt;  // never block on a FIFO or read a device
    std::ifstream f(path, std::ios::binary);
    if (!f) return std::nullopt;
    std::uint64_t h = 1469598103934665603ull;
    char buf[65536];
    while (f.read(buf, sizeof buf) || f.gcount() > 0) {
        for (std::streamsize i = 0; i < f.gcount(); ++i) {
            h ^= static_cast<unsigned char>(buf[i]);
            h *= 1099511628211ull;
        }
        if (!f) break;
    }
    return h;
}

namespace {

// The folder a file lives in and its name there, both absolute and plain.
std::pair<std::string, std::string> splitPath(const std::string& path) {
    std::filesystem::path p = std::filesystem::absolute(path).lexically_normal();
    return {p.parent_path().string(), p.filename().string()};
}

}  // namespace

FileMonitor::FileMonitor(std::chrono::milliseconds settle) : settle_(settle) {
    fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
}

FileMonitor::~FileMonitor() {
    if (fd_ >= 0) ::close(fd_);
}

void FileMonitor::follow(const std::vector<std::string>& paths) {
    entries_.clear();
    order_.clear();
    if (fd_ >= 0) {
        for (const auto& [wd, dir] : dirs_) ::inotify_rm_watch(fd_, wd);
        drainEvents();  // what the old folders reported no longer matters
    }
    dirs_.clear();
    byDir_.clear();
    for (const auto& p : paths) {
        if (entries_.count(p)) continue;
        entries_[p].known = hashFile(p);
        order_.push_back(p);
        auto [dir, name] = splitPath(p);
        byDir_[dir].insert(name);
    }
    if (fd_ < 0) return;
    const uint32_t mask = IN_CLOSE_WRITE | IN_MODIFY | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE |
                          IN_ATTRIB | IN_DELETE_SELF | IN_MOVE_SELF;
    for (const auto& [dir, names] : byDir_) {
        int wd = ::inotify_add_watch(fd_, dir.c_str(), mask);
        if (wd >= 0) dirs_[wd] = dir;
        else
            for (const auto& p : order_)  // a folder we cannot watch: hash its files every poll
                if (splitPath(p).first == dir) entries_[p].unwatched = true;
    }
}

void FileMonitor::drainEvents() {
    alignas(inotify_event) char buf[16384];
    for (;;) {
        ssize_t n = ::read(fd_, buf, sizeof buf);
        if (n <= 0) return;
        for (char* at = buf; at < buf + n;) {
            auto* ev = reinterpret_cast<inotify_event*>(at);
            at += sizeof(inotify_event) + ev->len;
            auto d = dirs_.find(ev->wd);
            if (d == dirs_.end()) continue;
            bool whole = (ev->mask & (IN_DELETE_SELF | IN_MOVE_SELF | IN_Q_OVERFLOW)) || ev->len == 0;
            std::string name = ev->len ? std::string(ev->name) : std::string();
            for (const auto& p : order_) {
                auto [dir, file] = splitPath(p);
                if (dir == d->second && (whole || file == name)) entries_[p].dirty = true;
            }
        }
    }
}

bool FileMonitor::busy() const {
    if (fd_ < 0) return !order_.empty();
    for (const auto& [p, e] : entries_)
        if (e.hasPending || e.dirty || e.unwatched) return true;
    return false;
}

std::vector<std::string> FileMonitor::poll(Clock::time_point now) {
    if (fd_ >= 0) drainEvents();
    std::vector<std::string> settled;
    for (const auto& path : order_) {
        Entry& e = entries_[path];
        // With inotify, a file the kernel did not name and that waits for
        // nothing has not changed: it is not read.
        if (fd_ >= 0 && !e.dirty && !e.hasPending && !e.unwatched) continue;
        e.dirty = false;
        auto h = hashFile(path);
        ++hashes_;
        if (h == e.known) {  // back to what we had (an editor's temporary state): nothing to do
            e.hasPending = false;
            continue;
        }
        if (!e.hasPending || h != e.pending) {  // a new content: start the settle clock
            e.pending = h;
            e.pendingSince = now;
            e.hasPending = true;
            continue;
        }
        if (now - e.pendingSince >= settle_) {
            e.known = h;
            e.hasPending = false;
            settled.push_back(path);
        }
    }
    return settled;
}

}  // namespace glimmer
