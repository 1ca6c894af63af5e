#include "view/window_fit.h"

#include <GLFW/glfw3.h>

#include <algorithm>

#include "view/view_model.h"
#include "view/wakeups.h"

namespace glimmer {

void WindowFit::pictureRect(int fbw, int fbh, bool panelShown, int panelW, int& x, int& y, int& w, int& h) const {
    x = y = 0;
    if (fullscreen_) {
        w = std::max(1, fbw - (panelShown ? panelW : 0));
        h = fbh;
        return;
    }
    w = width_;
    h = height_;
}

bool WindowFit::follow(Clock::time_point now, bool& resized) {
    resized = false;
    if (fullscreen_) return false;
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    if (fbw <= 0 || fbh <= 0) return false;
    if (fbw == reqW_ && fbh == reqH_) {
        resizeAt_ = Clock::time_point::max();
        return false;
    }
    // A window manager sends many sizes while an edge is dragged: the
    // picture is drawn again once the size has held for 150 ms.
    if (fbw != seenW_ || fbh != seenH_ || resizeAt_ == Clock::time_point::max()) {
        seenW_ = fbw;
        seenH_ = fbh;
        resizeAt_ = now + std::chrono::milliseconds(150);
        return false;
    }
    if (now < resizeAt_) return false;
    resizeAt_ = Clock::time_point::max();
    int nw = std::max(16, width_ + fbw - reqW_), nh = std::max(16, height_ + fbh - reqH_);
    reqW_ = fbw;
    reqH_ = fbh;
    if (nw != width_ || nh != height_) {
        width_ = nw;
        height_ = nh;
        resized = true;
    }
    return true;
}

void WindowFit::layout(bool panelShown, int panelW, int panelH) {
    if (fullscreen_) return;
    int maxH = 1000;
    if (GLFWmonitor* m = glfwGetPrimaryMonitor()) {
        int mx, my, mw, mh;
        glfwGetMonitorWorkarea(m, &mx, &my, &mw, &mh);
        if (mh > 200) maxH = mh - 40;
    }
    WindowLayout l = layoutWindow(width_, height_, panelShown, panelW, panelH, maxH);
    if (l.windowW != reqW_ || l.windowH != reqH_) {
        reqW_ = l.windowW;
        reqH_ = l.windowH;
        glfwSetWindowSize(window_, reqW_, reqH_);
        gInput = true;  // draw again at the new size
    }
}

void WindowFit::toggleFullscreen() {
    if (!fullscreen_) {
        GLFWmonitor* m = glfwGetPrimaryMonitor();
        const GLFWvidmode* mode = m ? glfwGetVideoMode(m) : nullptr;
        if (!mode) return;
        glfwGetWindowPos(window_, &savedX_, &savedY_);
        fullscreen_ = true;
        glfwSetWindowMonitor(window_, m, 0, 0, mode->width, mode->height, mode->refreshRate);
    } else {
        fullscreen_ = false;
        glfwSetWindowMonitor(window_, nullptr, savedX_, savedY_, reqW_, reqH_, 0);
    }
    gInput = true;
}

}  // namespace glimmer
