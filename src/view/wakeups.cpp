#include "view/wakeups.h"

#include <GLFW/glfw3.h>

#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <iostream>

#include "view/view_commands.h"

#include <cstdint>

namespace glimmer {

std::atomic<bool> gInput{false};
std::atomic<bool> gWindowAlive{false};
std::atomic<bool> gContentScaleChanged{false};
std::vector<int> gKeyPresses;

void wake() {
    if (gWindowAlive) glfwPostEmptyEvent();
}

namespace {
void markInput(GLFWwindow*) { gInput = true; }
}  // namespace

void installWakeCallbacks(GLFWwindow* w) {
    glfwSetWindowRefreshCallback(w, markInput);
    glfwSetCursorPosCallback(w, [](GLFWwindow* win, double, double) { markInput(win); });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int, int, int) { markInput(win); });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double, double) { markInput(win); });
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
        if (action == GLFW_PRESS) gKeyPresses.push_back(key);
        markInput(win);
    });
    glfwSetCharCallback(w, [](GLFWwindow* win, unsigned) { markInput(win); });
    glfwSetCursorEnterCallback(w, [](GLFWwindow* win, int) { markInput(win); });
    glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int) { markInput(win); });
    glfwSetFramebufferSizeCallback(w, [](GLFWwindow* win, int, int) { markInput(win); });
    glfwSetWindowContentScaleCallback(w, [](GLFWwindow* win, float, float) {
        gContentScaleChanged = true;
        markInput(win);
    });
}

void CommandQueue::push(std::string line) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        lines_.push_back(std::move(line));
    }
    wake();  // the loop sleeps in glfwWaitEvents until something happens
}

std::vector<std::string> CommandQueue::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out(lines_.begin(), lines_.end());
    lines_.clear();
    return out;
}

void CommandQueue::start(const std::string& exec, bool readStdin) {
    for (const auto& line : splitCommands(exec)) push(line);
    if (!readStdin) return;
    std::thread([this] {
        for (std::string line; std::getline(std::cin, line);)
            for (const auto& part : splitCommands(line)) push(part);
    }).detach();
}

FileWaker::FileWaker(int notifyFd) {
    if (notifyFd < 0) return;
    epoll_ = ::epoll_create1(EPOLL_CLOEXEC);
    stop_ = ::eventfd(0, EFD_CLOEXEC);
    if (epoll_ < 0 || stop_ < 0) return;
    epoll_event ev{};
    ev.events = EPOLLIN | EPOLLET;
    ev.data.fd = notifyFd;
    ::epoll_ctl(epoll_, EPOLL_CTL_ADD, notifyFd, &ev);
    ev.events = EPOLLIN;
    ev.data.fd = stop_;
    ::epoll_ctl(epoll_, EPOLL_CTL_ADD, stop_, &ev);
    thread_ = std::thread([this] {
        for (;;) {
            epoll_event got[2];
            int n = ::epoll_wait(epoll_, got, 2, -1);
            for (int i = 0; i < n; ++i)
                if (got[i].data.fd == stop_) return;
            if (n > 0) wake();
        }
    });
}

FileWaker::~FileWaker() {
    if (thread_.joinable()) {
        std::uint64_t one = 1;
        (void)!::write(stop_, &one, sizeof one);
        thread_.join();
    }
    if (epoll_ >= 0) ::close(epoll_);
    if (stop_ >= 0) ::close(stop_);
}

}  // namespace glimmer
