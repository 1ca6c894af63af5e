// A real `glimmer view` window under xvfb-run, driven through its standard
// input the way a test (or a teacher's script) would, with its stderr read
// back from a file.
#pragma once
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace glimmer_viewer {

class ViewerProcess {
public:
    // Starts `glimmer view` with `args` (after "view") in `workDir`, under
    // an X server of its own (xvfb-run), or on `display` (":N") when given.
    ViewerProcess(const std::vector<std::string>& args, const std::filesystem::path& workDir,
                  const std::string& display = {});
    ~ViewerProcess();  // quits, or kills the whole process group after a grace period
    ViewerProcess(const ViewerProcess&) = delete;
    ViewerProcess& operator=(const ViewerProcess&) = delete;

    void send(const std::string& line);
    // Waits until stderr holds `needle` at least `count` times; false on timeout.
    bool waitForLog(const std::string& needle, int count = 1, std::chrono::seconds timeout = std::chrono::seconds(30));
    std::string log() const;
    // Waits for the process to end on its own (a key, --exec quit); its
    // exit code, or -1 when it is still running at the deadline.
    int waitExit(std::chrono::seconds timeout);
    // Sends quit and waits; the exit code, or -1.
    int quit(std::chrono::seconds timeout = std::chrono::seconds(20));

private:
    int pid_ = -1;  // the leader of a process group of its own
    int stdinFd_ = -1;
    std::filesystem::path logPath_;
    bool exited_ = false;
    int exitCode_ = -1;
};

bool waitForFile(const std::filesystem::path& p, std::chrono::seconds timeout = std::chrono::seconds(30));
std::vector<unsigned char> readBytes(const std::filesystem::path& p);

}  // namespace glimmer_viewer
