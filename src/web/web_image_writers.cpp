// The browser build has no libpng, zlib or tinyexr (Emscripten's ports are
// not in Debian's package), so the file writers that need them answer with
// an error here; the page saves the canvas as PNG itself. Linked in place of
// src/image/png_write.cpp and src/image/deep_writers.cpp.
#include <string>

#include "image/image.h"

namespace glimmer {

namespace {
bool notHere(const std::string& what, const std::string& path, std::string& error) {
    error = "cannot write " + path + ": " + what + " files are not written by the browser build (save the picture from the page)";
    return false;
}
}  // namespace

bool writePng(const std::string& path, const Image&, std::string& error, int) { return notHere("PNG", path, error); }
bool writePng16(const std::string& path, const Image&, std::string& error) { return notHere("16-bit PNG", path, error); }
bool writeExr(const std::string& path, const Image&, std::string& error) { return notHere("OpenEXR", path, error); }

}  // namespace glimmer
