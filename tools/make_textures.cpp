// Writes the textures the project generates itself, so that every committed
// picture can be remade (and checked byte for byte by tests/image).
#include "image/test_images.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s TEXTURES_DIR\n", argv[0]);
        return 2;
    }
    const std::string path = std::string(argv[1]) + "/grid.bmp";
    std::string error;
    if (!glimmer::writeBmp(path, glimmer::makeGridImage(512, 512), error)) {
        std::fprintf(stderr, "glimmer-textures: %s\n", error.c_str());
        return 1;
    }
    std::printf("wrote %s\n", path.c_str());
    const std::string hdr = std::string(argv[1]) + "/hdr_scene.hdr";
    if (!glimmer::writeHdr(hdr, glimmer::makeHdrScene(512, 512), error)) {
        std::fprintf(stderr, "glimmer-textures: %s\n", error.c_str());
        return 1;
    }
    std::printf("wrote %s\n", hdr.c_str());
    return 0;
}
