#include "cli/run_glimmer.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <thread>

namespace glimmer_cli {
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace

TempDir::TempDir() {
    std::random_device rd;
    for (int attempt = 0; attempt < 100; ++attempt) {
        fs::path p = fs::temp_directory_path() /
                     ("glimmer-cli-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
        std::error_code ec;
        if (fs::create_directory(p, ec)) {
            path_ = p;
            return;
        }
    }
    throw std::runtime_error("cannot make a temp folder");
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

RunResult runGlimmer(const std::vector<std::string>& args, int timeoutSeconds) {
    return runGlimmerWithInput(args, "/dev/null", timeoutSeconds);
}

namespace {
RunResult runWith(const std::vector<std::string>& args, const std::string& stdinPath, int timeoutSeconds,
                  long maxFileBytes);
}

RunResult runGlimmerWithInput(const std::vector<std::string>& args, const std::string& stdinPath, int timeoutSeconds) {
    return runWith(args, stdinPath, timeoutSeconds, 0);
}

RunResult runGlimmerWithFileSizeLimit(const std::vector<std::string>& args, long maxFileBytes, int timeoutSeconds) {
    return runWith(args, "/dev/null", timeoutSeconds, maxFileBytes);
}

pid_t startGlimmer(const std::vector<std::string>& args, const std::string& logDir) {
    std::vector<std::string> argv0{GLIMMER_BIN};
    argv0.insert(argv0.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv0) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string out = logDir + "/stdout", err = logDir + "/stderr";
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        if (::chdir(GLIMMER_SOURCE_DIR) != 0) ::_exit(127);
        int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int in = ::open("/dev/null", O_RDONLY);
        if (o < 0 || e < 0 || in < 0) ::_exit(127);
        ::dup2(in, 0);
        ::dup2(o, 1);
        ::dup2(e, 2);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return pid;
}

std::vector<pid_t> childrenOf(pid_t parent) {
    std::vector<pid_t> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator("/proc", ec)) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::string stat = slurp(entry.path() / "stat");
        // "pid (comm) state ppid ...": comm may hold spaces and brackets.
        size_t close = stat.rfind(')');
        if (close == std::string::npos) continue;
        char state = 0;
        int ppid = 0;
        if (std::sscanf(stat.c_str() + close + 1, " %c %d", &state, &ppid) == 2 && ppid == parent)
            out.push_back(pid_t(std::stol(name)));
    }
    return out;
}

std::vector<pid_t> waitForChildren(pid_t parent, size_t count, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    std::vector<pid_t> kids = childrenOf(parent);
    while (kids.size() < count && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        kids = childrenOf(parent);
    }
    return kids;
}

void killAndReap(pid_t pid) {
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
}

bool waitUntilGone(pid_t pid, double seconds) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
        size_t close = stat.rfind(')');
        if (stat.empty() || (close != std::string::npos && close + 2 < stat.size() && stat[close + 2] == 'Z'))
            return true;
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
}

namespace {
RunResult runWith(const std::vector<std::string>& args, const std::string& stdinPath, int timeoutSeconds,
                  long maxFileBytes) {
    TempDir io;
    fs::path outPath = io.path() / "stdout", errPath = io.path() / "stderr";
    std::vector<std::string> argv0{GLIMMER_BIN};
    argv0.insert(argv0.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv0) argv.push_back(a.data());
    argv.push_back(nullptr);

    RunResult r;
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        if (::chdir(GLIMMER_SOURCE_DIR) != 0) ::_exit(127);  // first: stdinPath may be relative to it
        int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int in = ::open(stdinPath.c_str(), O_RDONLY);
        if (out < 0 || err < 0 || in < 0) ::_exit(127);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        if (maxFileBytes > 0) {
            rlimit limit{rlim_t(maxFileBytes), rlim_t(maxFileBytes)};
            ::setrlimit(RLIMIT_FSIZE, &limit);
        }
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    int status = 0;
    for (;;) {
        pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0) throw std::runtime_error("waitpid failed");
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            r.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!r.timedOut && WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    r.out = slurp(outPath);
    r.err = slurp(errPath);
    return r;
}
}  // namespace

bool readPngSize(const std::string& path, unsigned& width, unsigned& height) {
    std::ifstream f(path, std::ios::binary);
    unsigned char b[24] = {};
    if (!f.read(reinterpret_cast<char*>(b), sizeof b)) return false;
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    for (int i = 0; i < 8; ++i)
        if (b[i] != sig[i]) return false;
    if (b[12] != 'I' || b[13] != 'H' || b[14] != 'D' || b[15] != 'R') return false;
    auto be32 = [&](int at) {
        return unsigned(b[at]) << 24 | unsigned(b[at + 1]) << 16 | unsigned(b[at + 2]) << 8 | unsigned(b[at + 3]);
    };
    width = be32(16);
    height = be32(20);
    return true;
}

RunResult checkOnOsmesa(const std::string& script, const std::vector<std::string>& extra) {
    std::vector<std::string> args{"check", script, "--backend", "osmesa"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runGlimmer(args);
}

std::string writeFile(const TempDir& dir, const std::string& name, const std::string& text) {
    std::string p = dir.file(name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

glimmer::Image loadPicture(const std::string& path) {
    glimmer::Image img;
    std::string why;
    EXPECT_TRUE(glimmer::loadImage(path, img, why)) << why;
    return img;
}

std::string writeSolid(const TempDir& dir, const std::string& name, int k) {
    std::ofstream(dir.file(name)) << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nColor " << (k % 3 == 0) << " "
                                  << (k % 3 == 1) << " " << (k % 3 == 2) << "\nQuadXY 0 1\n";
    return dir.file(name);
}

TestFaultEnv::TestFaultEnv(const std::string& spec) { ::setenv("GLIMMER_TEST_FAULT", spec.c_str(), 1); }
TestFaultEnv::~TestFaultEnv() { ::unsetenv("GLIMMER_TEST_FAULT"); }

std::string readAll(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

int countOf(const std::string& haystack, const std::string& needle) {
    int n = 0;
    for (size_t at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + needle.size()))
        ++n;
    return n;
}

std::string cliData(const std::string& name) {
    return (fs::path(GLIMMER_TEST_DATA).lexically_relative(GLIMMER_SOURCE_DIR) / "cli" / name).string();
}

std::string writeRunawayScript(const TempDir& dir) {
    std::ofstream(dir.file("st.vert")) << "#version 330 compatibility\nout vec2 vST;\nvoid main() {\n"
                                          "    vST = gl_MultiTexCoord0.st;\n"
                                          "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n}\n";
    std::ofstream(dir.file("quick.frag")) << "#version 330 compatibility\nin vec2 vST;\n"
                                             "void main() { gl_FragColor = vec4(vST, 0., 1.); }\n";
    std::string body;
    for (int k = 0; k < 40; ++k)
        body += "        a = sin(a * 1.0001 + float(i) * 1e-5 + vST.s + " + std::to_string(k) + ".0);\n";
    std::ofstream(dir.file("slow.frag")) << "#version 330 compatibility\nuniform sampler2D Quick;\nin vec2 vST;\n"
                                            "void main() {\n    float a = texture(Quick, vST).r;\n"
                                            "    for (int i = 0; i < 60000; ++i) {\n" << body
                                         << "    }\n    gl_FragColor = vec4(a, 0., 0., 1.);\n}\n";
    std::ofstream(dir.file("slow.glib")) << "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nTexture2D 6 64 64\n"
                                            "Vertex st.vert\nRenderToTexture 6\nFragment quick.frag\nProgram Quick\n"
                                            "QuadXY 0 1\nRenderToTexture\nFragment slow.frag\nProgram Slow Quick 6\n"
                                            "QuadXY 0 1\n";
    return dir.file("slow.glib");
}


EnvVar::EnvVar(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) ::setenv(name, value, 1);
    else ::unsetenv(name);
}

EnvVar::~EnvVar() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
}

}  // namespace glimmer_cli
