// The GL a window front end needs outside any script: each frame starts by
// clearing the window's own framebuffer (0) to the panel's background,
// before the renderer presents a picture into it (Renderer::present) and
// ImGui's OpenGL backend draws the panel. It works with no script loaded (a
// first load that failed), so the viewer never calls GL itself.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "gl/proc_address.h"

namespace glimmer {

struct GlApi;

class WindowFrame {
public:
    ~WindowFrame();
    // Null and `error` when the driver lacks what Glimmer needs. The window's
    // context must be current.
    static std::unique_ptr<WindowFrame> create(const GetProcAddress& getProc, std::string& error);
    // Binds framebuffer 0 at width x height and clears it to this colour.
    void begin(int width, int height, float r, float g, float b) const;
    // A hash (FNV-1a) of the RGBA bytes framebuffer 0 holds in the rectangle
    // at (x, y) from the top left, w x h, of a window `windowH` tall: what the
    // `panel` command reports as `picture=`, so a tour that clicks a control
    // sees whether the picture on screen changed (view/panel.h).
    std::uint64_t hashRegion(int x, int y, int w, int h, int windowH) const;

private:
    WindowFrame();
    std::unique_ptr<GlApi> gl_;
};

}  // namespace glimmer
