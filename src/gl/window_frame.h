// The GL a window front end needs outside any script: each frame starts by
// clearing the window's own framebuffer (0) to the panel's background,
// before the renderer presents a picture into it (Renderer::present) and
// ImGui's OpenGL backend draws the panel. It works with no script loaded (a
// first load that failed), so the viewer never calls GL itself.
#pragma once
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

private:
    WindowFrame();
    std::unique_ptr<GlApi> gl_;
};

}  // namespace glimmer
