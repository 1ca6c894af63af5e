#include "x11_driver.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

namespace glimmer_viewer {

std::string shellOutput(const std::string& cmd) {
    std::string out;
    if (FILE* f = ::popen(cmd.c_str(), "r")) {
        char buf[4096];
        for (size_t n; (n = fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
        ::pclose(f);
    }
    return out;
}

namespace fs = std::filesystem;

namespace {

std::string envOf(int pid, const std::string& name) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/environ", std::ios::binary);
    std::string all{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    std::stringstream ss(all);
    for (std::string kv; std::getline(ss, kv, '\0');)
        if (kv.rfind(name + "=", 0) == 0) return kv.substr(name.size() + 1);
    return {};
}

}  // namespace

std::optional<XViewer> findViewer(const fs::path& workDir, std::chrono::seconds timeout) {
    auto end = std::chrono::steady_clock::now() + timeout;
    std::error_code ec;
    fs::path want = fs::canonical(workDir, ec);
    while (std::chrono::steady_clock::now() < end) {
        for (const auto& e : fs::directory_iterator("/proc", ec)) {
            std::string name = e.path().filename().string();
            if (name.find_first_not_of("0123456789") != std::string::npos) continue;
            std::ifstream comm(e.path() / "comm");
            std::string c;
            std::getline(comm, c);
            if (c != "glimmer") continue;
            std::error_code ec2;
            if (fs::read_symlink(e.path() / "cwd", ec2) != want) continue;
            XViewer v;
            v.pid = std::stoi(name);
            v.env = "DISPLAY=" + envOf(v.pid, "DISPLAY") + " XAUTHORITY=" + envOf(v.pid, "XAUTHORITY");
            std::string id = shellOutput(v.env + " xdotool search --name '^Glimmer - ' 2>/dev/null");
            if (id.empty()) continue;
            v.window = id.substr(0, id.find('\n'));
            return v;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return std::nullopt;
}

std::string xdotool(const XViewer& v, const std::string& args) { return shellOutput(v.env + " xdotool " + args + " 2>&1"); }

bool windowSize(const XViewer& v, int& w, int& h) {
    std::string g = xdotool(v, "getwindowgeometry " + v.window);
    auto at = g.find("Geometry: ");
    return at != std::string::npos && std::sscanf(g.c_str() + at, "Geometry: %dx%d", &w, &h) == 2;
}

glimmer::Image captureWindow(const XViewer& v, const fs::path& scratch) {
    fs::path png = scratch / "capture.png";
    shellOutput(v.env + " /usr/bin/import -window " + v.window + " " + png.string() + " 2>&1");
    glimmer::Image img;
    std::string why;
    glimmer::loadImage(png.string(), img, why);
    return img;
}

double cpuSeconds(int pid) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
    std::string all{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    // Fields after the command name (which may hold spaces) in parentheses.
    std::stringstream ss(all.substr(all.rfind(')') + 2));
    std::string field;
    long utime = 0, stime = 0;
    for (int i = 3; ss >> field; ++i) {
        if (i == 14) utime = std::stol(field);
        if (i == 15) {
            stime = std::stol(field);
            break;
        }
    }
    return double(utime + stime) / double(::sysconf(_SC_CLK_TCK));
}

}  // namespace glimmer_viewer
