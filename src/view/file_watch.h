// Notices when files a script uses have changed, and only once their
// content has settled: editors that truncate first, or write twice, must
// not cause a reload of a half-written file or two reloads.
#pragma once
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glimmer {

class FileWatch {
public:
    using Clock = std::chrono::steady_clock;

    // `settle`: how long a changed content must stay the same before it
    // counts. Polling every ~25 ms with 60 ms settle reloads well within
    // 200 ms of a save.
    explicit FileWatch(std::chrono::milliseconds settle = std::chrono::milliseconds(60)) : settle_(settle) {}

    // Starts watching exactly these files, taking their current content as
    // the known state.
    void watch(const std::vector<std::string>& paths);

    // Reads the files again. Returns the files whose content changed and has
    // stayed the same for `settle`, and takes that content as the new known
    // state; empty when nothing settled yet.
    std::vector<std::string> poll(Clock::time_point now = Clock::now());

    const std::vector<std::string>& paths() const { return order_; }

private:
    struct Entry {
        std::optional<std::uint64_t> known;    // hash of the content last reported (nullopt: missing)
        std::optional<std::uint64_t> pending;  // a different content seen since
        Clock::time_point pendingSince{};
        bool hasPending = false;
    };
    std::chrono::milliseconds settle_;
    std::map<std::string, Entry> entries_;
    std::vector<std::string> order_;
};

// FNV-1a of a file's bytes; nullopt when it cannot be read.
std::optional<std::uint64_t> hashFile(const std::string& path);

}  // namespace glimmer
