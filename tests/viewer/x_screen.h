// What a person would see: a virtual X screen of a known size (Xvfb, on a
// display it picks itself), and its contents read back with xwd, the X
// Window Dump tool, decoded here rather than through ImageMagick.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer_viewer {

class VirtualScreen {
public:
    // Starts Xvfb with one width x height x 24 screen and a black root
    // window; display() is empty when it did not start (see why()).
    VirtualScreen(int width, int height);
    ~VirtualScreen();  // stops the server
    VirtualScreen(const VirtualScreen&) = delete;
    VirtualScreen& operator=(const VirtualScreen&) = delete;

    const std::string& display() const { return display_; }  // ":N"
    const std::string& why() const { return why_; }
    // The whole screen as it is now (xwd -root), RGBA8, alpha 255.
    bool capture(glimmer::Image& out, std::string& error) const;

private:
    int pid_ = -1;
    std::string display_;
    std::string why_;
};

// A ZPixmap X Window Dump of a TrueColor or DirectColor visual (8 to 32 bits
// a pixel, either byte order) as RGBA8. False with a reason otherwise.
bool decodeXwd(const std::vector<std::uint8_t>& bytes, glimmer::Image& out, std::string& error);

}  // namespace glimmer_viewer
