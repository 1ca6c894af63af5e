#include "viewer_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <thread>

namespace glimmer_viewer {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

ViewerProcess::ViewerProcess(const std::vector<std::string>& args, const fs::path& workDir,
                             const std::string& display) {
    // The viewer may quit on its own (--exec ... quit); a later write to its
    // stdin must fail quietly, not kill the test.
    ::signal(SIGPIPE, SIG_IGN);
    static int counter = 0;
    logPath_ = fs::temp_directory_path() / ("glimmer_viewer_" + std::to_string(::getpid()) + "_" +
                                            std::to_string(counter++) + ".log");
    int pipeFds[2];
    if (::pipe(pipeFds) != 0) return;
    std::vector<std::string> argv = {"xvfb-run", "-a", "-s", "-screen 0 1024x768x24", GLIMMER_BIN, "view"};
    if (!display.empty()) argv = {GLIMMER_BIN, "view"};
    argv.insert(argv.end(), args.begin(), args.end());
    pid_ = ::fork();
    if (pid_ == 0) {
        ::setpgid(0, 0);  // its own group, so a kill reaches Xvfb too
        ::dup2(pipeFds[0], 0);
        int log = ::open(logPath_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(log, 1);
        ::dup2(log, 2);
        ::close(pipeFds[1]);
        if (::chdir(workDir.c_str()) != 0) ::_exit(126);
        if (!display.empty()) ::setenv("DISPLAY", display.c_str(), 1);
        std::vector<char*> cargs;
        for (auto& a : argv) cargs.push_back(a.data());
        cargs.push_back(nullptr);
        ::execvp(cargs[0], cargs.data());
        ::_exit(127);
    }
    ::close(pipeFds[0]);
    stdinFd_ = pipeFds[1];
}

ViewerProcess::~ViewerProcess() {
    if (pid_ > 0 && !exited_) quit(std::chrono::seconds(5));
    if (pid_ > 0 && !exited_) {
        ::kill(-pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
    if (stdinFd_ >= 0) ::close(stdinFd_);
    std::error_code ec;
    fs::remove(logPath_, ec);
}

void ViewerProcess::send(const std::string& line) {
    std::string l = line + "\n";
    if (stdinFd_ >= 0) (void)!::write(stdinFd_, l.data(), l.size());
}

std::string ViewerProcess::log() const {
    std::ifstream f(logPath_);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

bool ViewerProcess::waitForLog(const std::string& needle, int count, std::chrono::seconds timeout) {
    auto end = Clock::now() + timeout;
    while (Clock::now() < end) {
        std::string l = log();
        int n = 0;
        for (size_t p = l.find(needle); p != std::string::npos; p = l.find(needle, p + 1)) ++n;
        if (n >= count) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

int ViewerProcess::quit(std::chrono::seconds timeout) {
    if (exited_) return exitCode_;
    send("quit");
    return waitExit(timeout);
}

int ViewerProcess::waitExit(std::chrono::seconds timeout) {
    if (exited_) return exitCode_;
    auto end = Clock::now() + timeout;
    while (Clock::now() < end) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            exited_ = true;
            exitCode_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
            return exitCode_;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return -1;
}

bool waitForFile(const fs::path& p, std::chrono::seconds timeout) {
    auto end = Clock::now() + timeout;
    while (Clock::now() < end) {
        std::error_code ec;
        if (fs::exists(p, ec) && fs::file_size(p, ec) > 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));  // let the writer finish
            return true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

std::vector<unsigned char> readBytes(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace glimmer_viewer
