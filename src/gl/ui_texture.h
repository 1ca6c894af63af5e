// A picture made on the CPU, as a texture that ImGui's OpenGL backend can
// draw (ImGui::Image, ImDrawList::AddImage): the viewer's "Show values"
// overlay, drawn by image/ttf_text.h's labelLayer so that the window shows
// the very pixels a saved PNG gets. Here, so the viewer calls no GL itself.
#pragma once
#include <memory>
#include <string>

#include "gl/proc_address.h"
#include "image/image.h"

namespace glimmer {

struct GlApi;

class UiTexture {
public:
    ~UiTexture();
    // Null and `error` when the driver lacks what it needs; the context must be current.
    static std::unique_ptr<UiTexture> create(const GetProcAddress& getProc, std::string& error);
    // Replaces the texture's content with `rgba8` (row 0 at the top, as ImGui
    // draws it); returns the GL name, 0 for an empty or non-RGBA8 image.
    unsigned upload(const Image& rgba8);

private:
    UiTexture();
    std::unique_ptr<GlApi> gl_;
    unsigned id_ = 0;
};

}  // namespace glimmer
