// Starting a render target black on the GPU: a 16384^2 RGBA target would
// otherwise need a 4 GiB buffer of zeros on the CPU to upload.
#pragma once
#include "gl/gl_api.h"

namespace glimmer {

// Clears level 0 of the 2-D texture `texture` (already given storage) to
// transparent black through a temporary framebuffer. Leaves framebuffer 0
// bound and the clear colour at 0 0 0 0.
void clearTexture2D(const GlApi& gl, unsigned texture);

}  // namespace glimmer
