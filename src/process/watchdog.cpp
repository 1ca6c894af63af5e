#include "process/watchdog.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <fmt/format.h>

#include "process/child_guard.h"
#include "plan/limits.h"
#include "util/read_file.h"

namespace glimmer {
namespace {

int gProgressFd = -1;  // the write end, in the child

struct PassRecord {
    int line = 0, col = 0;
};

std::string stoppedMessage(double seconds, const std::string& script, const PassRecord& last, bool started) {
    std::string what = fmt::format("stopped after {:g} s (--timeout {:g})", seconds, seconds);
    if (!started) return fmt::format("{}: error: {} while loading and compiling the script\n", script, what);
    Diagnostics d;
    SourceTexts sources;
    std::string text, why;
    if (readRegularFile(script, kMaxScriptBytes, text, why)) sources.add(script, text);
    d.error(script, {last.line, last.col}, what + ": the pass that starts here was still drawing");
    std::string out = formatDiagnostic(d.all().front(), sources);
    return out + (out.empty() || out.back() != '\n' ? "\n" : "");
}

}  // namespace

bool passesWatched() { return gProgressFd >= 0; }

void reportPassStart(SourceLoc loc) {
    if (gProgressFd < 0) return;
    PassRecord r{loc.line, loc.col};
    (void)!::write(gProgressFd, &r, sizeof r);
}

int runWithTimeout(double seconds, const std::string& script, const std::function<int()>& work,
                   std::uint64_t addressSpaceBytes) {
    if (!(seconds > 0) && addressSpaceBytes == 0) return work();
    if (!(seconds > 0)) seconds = 1e9;  // only the address space is bounded: wait as long as it takes
    int fds[2];
    if (::pipe(fds) != 0) return work();
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    const pid_t parent = ::getpid();
    pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        std::cerr << "glimmer: error: --timeout: cannot start a child process\n";
        return 1;
    }
    if (pid == 0) {
        guardChild(parent, addressSpaceBytes);
        ::close(fds[0]);
        gProgressFd = fds[1];
        int code = work();
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        ::_exit(code);
    }
    ::close(fds[1]);
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    PassRecord last;
    bool started = false, pipeOpen = true;
    int status = 0;
    for (;;) {
        pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            // Passes announced after the last read are still in the pipe.
            PassRecord r;
            while (pipeOpen && ::read(fds[0], &r, sizeof r) == sizeof r) last = r, started = true;
            ::close(fds[0]);
            std::cerr << stoppedMessage(seconds, script, last, started);
            return 1;
        }
        if (!pipeOpen) {  // the child closed its end (it is exiting): just wait
            ::usleep(2000);
            continue;
        }
        pollfd p{fds[0], POLLIN, 0};
        int n = ::poll(&p, 1, int(std::min<long long>(left, 50)));
        if (n > 0) {
            PassRecord r;
            ssize_t got = ::read(fds[0], &r, sizeof r);
            if (got == sizeof r) last = r, started = true;
            else if (got == 0) pipeOpen = false;
        }
    }
    ::close(fds[0]);
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    std::cerr << fmt::format("{}: error: the renderer was stopped by signal {} ({}){}\n", script, WTERMSIG(status),
                             strsignal(WTERMSIG(status)),
                             addressSpaceBytes > 0
                                 ? fmt::format("; under --sandbox it may map at most {} MiB (--max-memory plus {} MiB "
                                               "for the driver): the script or its shaders may need more",
                                               addressSpaceBytes >> 20, kDriverHeadroomMiB)
                                 : "");
    return 1;
}

}  // namespace glimmer
