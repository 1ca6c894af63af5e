// How `glimmer view`'s window and its picture follow each other (GLFW): the
// picture at its exact size at the top left with the panel docked to its
// right, the window asked for the size that holds both; a size the user
// drags the window to is added to the picture's once the dragging stops;
// fullscreen fits the picture into what the panel leaves. The shell's
// only geometry; the page lays its canvas out with the same layoutWindow.
#pragma once
#include <chrono>

struct GLFWwindow;

namespace glimmer {

class WindowFit {
public:
    using Clock = std::chrono::steady_clock;
    WindowFit(GLFWwindow* window, int pictureW, int pictureH)
        : window_(window), width_(pictureW), height_(pictureH), reqW_(pictureW), reqH_(pictureH) {}

    int pictureW() const { return width_; }
    int pictureH() const { return height_; }
    bool fullscreen() const { return fullscreen_; }
    // A drag of the window's edge still settling: the shell polls meanwhile.
    bool settling() const { return resizeAt_ != Clock::time_point::max(); }

    // Where the picture is drawn in a framebuffer of fbw x fbh (top-left
    // origin), with a panel `panelW` wide beside it when shown.
    void pictureRect(int fbw, int fbh, bool panelShown, int panelW, int& x, int& y, int& w, int& h) const;
    // Follows a size the user gave the window. True when the window changed
    // (draw again); `resized` when the picture's size changed with it (load
    // the script again at pictureW() x pictureH()).
    bool follow(Clock::time_point now, bool& resized);
    // Asks for the window size that holds the picture and a panel of this size.
    void layout(bool panelShown, int panelW, int panelH);
    void toggleFullscreen();

private:
    GLFWwindow* window_;
    int width_, height_;  // the picture
    int reqW_, reqH_;     // the window size last asked for
    int seenW_ = 0, seenH_ = 0;
    Clock::time_point resizeAt_ = Clock::time_point::max();
    bool fullscreen_ = false;
    int savedX_ = 0, savedY_ = 0;
};

}  // namespace glimmer
