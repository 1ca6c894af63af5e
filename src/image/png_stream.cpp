#include "image/png_stream.h"

#include <cstdio>

namespace glimmer {

// encodePng: src/image/png_write.cpp.

bool writePngToStdout(const Image& img, std::string& error, int level) {
    std::vector<std::uint8_t> bytes = encodePng(img, level);
    if (bytes.empty()) {
        error = "cannot encode the picture as PNG";
        return false;
    }
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0) {
        error = "cannot write the PNG to standard output";
        return false;
    }
    return true;
}

}  // namespace glimmer
