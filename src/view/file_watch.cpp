#include "view/file_watch.h"

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

void FileWatch::watch(const std::vector<std::string>& paths) {
    entries_.clear();
    order_.clear();
    for (const auto& p : paths) {
        if (entries_.count(p)) continue;
        entries_[p].known = hashFile(p);
        order_.push_back(p);
    }
}

std::vector<std::string> FileWatch::poll(Clock::time_point now) {
    std::vector<std::string> settled;
    for (const auto& path : order_) {
        Entry& e = entries_[path];
        auto h = hashFile(path);
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
