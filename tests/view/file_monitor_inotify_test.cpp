// The watch is quiet when nothing changes: the kernel says which file to
// read, so an idle viewer hashes nothing, and a save by renaming a new file
// over the old one (as many editors do) is still seen.
#include <poll.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "view/file_monitor.h"

using namespace glimmer;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

struct Folder {
    fs::path dir = fs::temp_directory_path() / ("glimmer_inotify_" + std::to_string(::getpid()));
    Folder() {
        fs::remove_all(dir);
        fs::create_directories(dir);
        write("a.frag", "one");
        write("b.frag", "two");
    }
    ~Folder() { fs::remove_all(dir); }
    void write(const std::string& name, const std::string& s) const {
        std::ofstream(dir / name, std::ios::binary | std::ios::trunc) << s;
    }
    std::string path(const std::string& name) const { return (dir / name).string(); }
};

bool readable(int fd) {
    pollfd p{fd, POLLIN, 0};
    return ::poll(&p, 1, 0) == 1;
}

TEST(FileMonitorInotify, AnIdleWatchReadsNoFile) {
    Folder f;
    FileMonitor w(60ms);
    w.follow({f.path("a.frag"), f.path("b.frag")});
    ASSERT_GE(w.notifyFd(), 0);
    auto t0 = FileMonitor::Clock::now();
    for (int i = 0; i < 100; ++i) EXPECT_TRUE(w.poll(t0 + i * 25ms).empty());
    EXPECT_EQ(w.hashesDone(), 0u);
    EXPECT_FALSE(w.busy());
    EXPECT_FALSE(readable(w.notifyFd()));
}

TEST(FileMonitorInotify, OnlyTheChangedFileIsRead) {
    Folder f;
    FileMonitor w(60ms);
    w.follow({f.path("a.frag"), f.path("b.frag")});
    f.write("b.frag", "three");
    EXPECT_TRUE(readable(w.notifyFd()));
    auto t0 = FileMonitor::Clock::now();
    EXPECT_TRUE(w.poll(t0).empty());
    EXPECT_TRUE(w.busy());  // waiting for it to settle
    auto changed = w.poll(t0 + 80ms);
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(changed[0], f.path("b.frag"));
    EXPECT_EQ(w.hashesDone(), 2u);  // b twice; a never
    EXPECT_FALSE(w.busy());
    EXPECT_FALSE(readable(w.notifyFd()));
}

TEST(FileMonitorInotify, ARenameOverTheFileIsSeen) {
    Folder f;
    FileMonitor w(60ms);
    w.follow({f.path("a.frag")});
    f.write("a.frag.tmp", "saved by rename");
    fs::rename(f.dir / "a.frag.tmp", f.dir / "a.frag");
    auto t0 = FileMonitor::Clock::now();
    EXPECT_TRUE(w.poll(t0).empty());
    EXPECT_EQ(w.poll(t0 + 80ms).size(), 1u);
}

}  // namespace
