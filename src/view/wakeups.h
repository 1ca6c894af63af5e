// What wakes the viewer's loop, which otherwise sleeps in glfwWaitEvents
// (an idle viewer draws nothing and uses no CPU): input on the window, a
// command from stdin or --exec, a change to a watched file.
#pragma once
#include <atomic>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

struct GLFWwindow;

namespace glimmer {

// Set by the window's callbacks (chained before ImGui's): something the user
// did, or the window was exposed, so a frame must be drawn.
extern std::atomic<bool> gInput;
// Cleared before GLFW shuts down, so a thread that wakes the loop stops doing so.
extern std::atomic<bool> gWindowAlive;
// Set by GLFW when the window's content scale changes (another monitor).
extern std::atomic<bool> gContentScaleChanged;
// Keys pressed since the last frame, in order. ImGui 1.86 (Debian's) keeps
// only whether a key is down at the frame: a press and its release handled in
// one batch of events (a quick tap while a frame renders, xdotool's `key`)
// would never be seen, so presses are queued here. Main thread only.
extern std::vector<int> gKeyPresses;

// Wakes the loop from any thread.
void wake();

// Installed before ImGui's backend, which keeps and calls them: any input
// marks that a frame is due.
void installWakeCallbacks(GLFWwindow* w);

// Commands arrive from --exec, from standard input (a thread of its own, so
// a silent stdin never blocks the window) and from the panel's buttons.
class CommandQueue {
public:
    void push(std::string line);
    std::vector<std::string> take();
    // --exec's commands, then (when `readStdin`) standard input's lines as
    // they come, on a thread of its own. A line may hold several commands
    // separated by ';', as --exec does (issue 39: `set uAdd 2; set uHalfSize 11`
    // on one line was refused).
    void start(const std::string& exec, bool readStdin);

private:
    std::mutex mutex_;
    std::deque<std::string> lines_;
};

// Sleeps on the file watch's inotify descriptor and wakes the window's
// loop when the kernel reports a change; the loop itself reads the events.
// Edge-triggered, so unread events do not make it spin.
class FileWaker {
public:
    explicit FileWaker(int notifyFd);
    ~FileWaker();
    FileWaker(const FileWaker&) = delete;
    FileWaker& operator=(const FileWaker&) = delete;

private:
    int epoll_ = -1, stop_ = -1;
    std::thread thread_;
};

}  // namespace glimmer
