// Runs the real glimmer program for the end-to-end tests: its exit code,
// stdout and stderr, with a time limit.
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer_cli {

struct RunResult {
    int exitCode = -1;      // the process's exit status; -1 if it did not exit normally
    bool timedOut = false;  // killed after the time limit
    std::string out, err;
};

// Runs GLIMMER_BIN with `args` in the repository root (so script paths and the
// file names in diagnostics are relative to it). No shell is involved.
RunResult runGlimmer(const std::vector<std::string>& args, int timeoutSeconds = 60);
// The same with standard input read from the file `stdinPath` (absolute, or
// relative to the repository root).
RunResult runGlimmerWithInput(const std::vector<std::string>& args, const std::string& stdinPath,
                              int timeoutSeconds = 60);

// The same, with standard input from /dev/null and at most `maxFileBytes`
// per file it writes (RLIMIT_FSIZE: a full disk, as the program sees it).
RunResult runGlimmerWithFileSizeLimit(const std::vector<std::string>& args, long maxFileBytes,
                                      int timeoutSeconds = 60);

// Starts GLIMMER_BIN with `args` in the repository root, its output to files
// in `logDir`, and returns at once: its pid (the caller waits for it).
pid_t startGlimmer(const std::vector<std::string>& args, const std::string& logDir);
// The pids whose parent is `parent`, from /proc.
std::vector<pid_t> childrenOf(pid_t parent);
// Waits up to `seconds` for `parent` to have `count` children, looking every
// 5 ms (a test that stops the parent at once needs to see the child early):
// the children seen last, fewer than `count` when the time ran out.
std::vector<pid_t> waitForChildren(pid_t parent, size_t count, double seconds);
// Waits up to `seconds` for `pid` to end (gone, or a zombie no one reaps);
// true when it did.
bool waitUntilGone(pid_t pid, double seconds);
// Ends a glimmer startGlimmer started, at once (SIGKILL), and reaps it.
void killAndReap(pid_t pid);

// A fresh, empty folder under the system temp folder, removed at destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

// The width and height from a PNG's IHDR chunk; false when the file is not a
// PNG (wrong signature, or no IHDR first).
bool readPngSize(const std::string& path, unsigned& width, unsigned& height);

// How many times `needle` occurs in `haystack`.
int countOf(const std::string& haystack, const std::string& needle);

// A small script in `dir` that draws a colour picked by `k` (red, green,
// blue in turn), so scripts with different k give different PNGs.
std::string writeSolid(const TempDir& dir, const std::string& name, int k);

// Sets GLIMMER_TEST_FAULT (src/process/test_fault.h: a lost GPU picture,
// zeros, a stuck worker) for the glimmer processes a test starts, until it
// goes out of scope.
struct TestFaultEnv {
    explicit TestFaultEnv(const std::string& spec);
    ~TestFaultEnv();
    TestFaultEnv(const TestFaultEnv&) = delete;
    TestFaultEnv& operator=(const TestFaultEnv&) = delete;
};

// The whole of a file as bytes ("" when it cannot be read).
std::string readAll(const std::filesystem::path& path);

// `glimmer check SCRIPT --backend osmesa EXTRA...`.
RunResult checkOnOsmesa(const std::string& script, const std::vector<std::string>& extra = {});

// Writes `text` as the file `name` in `dir`; its path.
std::string writeFile(const TempDir& dir, const std::string& name, const std::string& text);

// A picture glimmer wrote (PNG, BMP, ...), decoded; empty, with a test
// failure, when it cannot be read.
glimmer::Image loadPicture(const std::string& path);

// Test data scripts, relative to the repository root: "tests/data/cli/NAME".
std::string cliData(const std::string& name);

// slow.glib in `dir` (with st.vert, quick.frag, slow.frag): forty sines an
// iteration, 60000 iterations (llvmpipe caps a loop at 65535), for every
// pixel: minutes on llvmpipe, and no compiler can fold it away (each sine
// feeds the next). The runaway pass is the second, the screen pass at line 9
// (RenderToTexture); the first, into unit 6, is quick. For --timeout tests.
std::string writeRunawayScript(const TempDir& dir);

// Sets (or unsets) one environment variable for the life of the object; the
// children runGlimmer starts inherit it.
class EnvVar {
public:
    EnvVar(const char* name, const char* value);
    ~EnvVar();
    EnvVar(const EnvVar&) = delete;
    EnvVar& operator=(const EnvVar&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace glimmer_cli
