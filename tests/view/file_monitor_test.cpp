// The viewer's reload trigger: a change counts only once the file's content
// has stayed the same for the settle time, so an editor that truncates
// first or writes twice causes one reload of the finished file.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "view/file_monitor.h"

using namespace glimmer;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

struct TempFile {
    fs::path path = fs::temp_directory_path() / ("glimmer_watch_" + std::to_string(::getpid()) + ".frag");
    TempFile() { write("one"); }
    ~TempFile() { fs::remove(path); }
    void write(const std::string& s) const { std::ofstream(path, std::ios::binary | std::ios::trunc) << s; }
};

TEST(FileMonitor, ReportsAChangeOnlyAfterItSettles) {
    TempFile f;
    FileMonitor w(60ms);
    w.follow({f.path.string()});
    auto t0 = FileMonitor::Clock::now();
    EXPECT_TRUE(w.poll(t0).empty());
    f.write("two");
    EXPECT_TRUE(w.poll(t0 + 10ms).empty());   // just seen: not settled
    EXPECT_TRUE(w.poll(t0 + 40ms).empty());
    auto changed = w.poll(t0 + 80ms);          // same content for 70 ms
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(changed[0], f.path.string());
    EXPECT_TRUE(w.poll(t0 + 200ms).empty());  // reported once
}

TEST(FileMonitor, TruncateThenWriteIsOneChange) {
    TempFile f;
    FileMonitor w(60ms);
    w.follow({f.path.string()});
    auto t0 = FileMonitor::Clock::now();
    f.write("");  // the editor truncates...
    EXPECT_TRUE(w.poll(t0 + 5ms).empty());
    f.write("three");  // ...then writes: the settle clock starts again
    EXPECT_TRUE(w.poll(t0 + 50ms).empty());
    EXPECT_TRUE(w.poll(t0 + 100ms).empty());
    EXPECT_EQ(w.poll(t0 + 120ms).size(), 1u);
}

TEST(FileMonitor, WritingTheSameContentBackIsNoChange) {
    TempFile f;
    FileMonitor w(60ms);
    w.follow({f.path.string()});
    auto t0 = FileMonitor::Clock::now();
    f.write("temporary");
    EXPECT_TRUE(w.poll(t0 + 5ms).empty());
    f.write("one");  // saved back as it was
    EXPECT_TRUE(w.poll(t0 + 100ms).empty());
    EXPECT_TRUE(w.poll(t0 + 300ms).empty());
}

TEST(FileMonitor, AFileThatDisappearsAndComesBackCounts) {
    TempFile f;
    FileMonitor w(60ms);
    w.follow({f.path.string()});
    auto t0 = FileMonitor::Clock::now();
    fs::remove(f.path);
    EXPECT_TRUE(w.poll(t0 + 5ms).empty());
    EXPECT_EQ(w.poll(t0 + 100ms).size(), 1u);  // gone, and stayed gone
    f.write("back");
    EXPECT_TRUE(w.poll(t0 + 110ms).empty());
    EXPECT_EQ(w.poll(t0 + 200ms).size(), 1u);
}

}  // namespace
