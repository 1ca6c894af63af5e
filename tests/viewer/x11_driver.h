// Drives a `glimmer view` window the way a person does, with xdotool on the
// virtual X server xvfb-run made for it, and reads what it costs: the
// viewer's process is found by its working folder, its DISPLAY and
// XAUTHORITY read from its environment.
#pragma once
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "image/image.h"

namespace glimmer_viewer {

struct XViewer {
    int pid = -1;
    std::string env;     // "DISPLAY=... XAUTHORITY=..." for the commands below
    std::string window;  // X window id of the viewer
};

// The glimmer process whose working folder is `workDir`, once its window is up.
std::optional<XViewer> findViewer(const std::filesystem::path& workDir,
                                  std::chrono::seconds timeout = std::chrono::seconds(30));
// Runs a shell command; its standard output.
std::string shellOutput(const std::string& cmd);
// Runs `xdotool ARGS` on the viewer's display; its standard output.
std::string xdotool(const XViewer& v, const std::string& args);
// The window's size, from xdotool getwindowgeometry.
bool windowSize(const XViewer& v, int& w, int& h);
// The window's pixels (import -window), row 0 at the top.
glimmer::Image captureWindow(const XViewer& v, const std::filesystem::path& scratch);
// User plus system CPU seconds the process has used so far.
double cpuSeconds(int pid);

}  // namespace glimmer_viewer
