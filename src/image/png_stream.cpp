#include "image/png_stream.h"

#include <cstdio>

#include <stb/stb_image_write.h>

namespace glimmer {

std::vector<std::uint8_t> encodePng(const Image& img) {
    std::vector<std::uint8_t> out;
    if (img.type != Image::Type::U8 || img.empty() || img.u8.size() != size_t(img.width) * size_t(img.height) * 4)
        return out;
    auto append = [](void* context, void* data, int size) {
        auto* v = static_cast<std::vector<std::uint8_t>*>(context);
        auto* bytes = static_cast<std::uint8_t*>(data);
        v->insert(v->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &out, img.width, img.height, 4, img.u8.data(), img.width * 4)) out.clear();
    return out;
}

bool writePngToStdout(const Image& img, std::string& error) {
    std::vector<std::uint8_t> bytes = encodePng(img);
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
