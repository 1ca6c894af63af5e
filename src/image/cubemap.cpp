#include "image/cubemap.h"

#include <utility>
#include <vector>

namespace glimmer {
namespace {

std::string sizeText(const Image& img) { return std::to_string(img.width) + "x" + std::to_string(img.height); }

}  // namespace

bool loadCubeMap(const std::array<std::string, 6>& paths, std::array<Image, 6>& faces, std::string& error) {
    std::array<Image, 6> loaded;
    for (std::size_t i = 0; i < 6; ++i) {
        std::string why;
        if (!loadImage(paths[i], loaded[i], why)) {
            error = std::string("cube map face ") + kCubeFaceNames[i] + ": " + why;
            return false;
        }
        const Image& f = loaded[i];
        const std::string who = std::string("cube map face ") + kCubeFaceNames[i] + " (" + paths[i] + ") is " + sizeText(f);
        if (f.width != f.height) {
            error = who + "; faces must be square";
            return false;
        }
        if (i > 0 && f.width != loaded[0].width) {
            error = who + ", but face +x is " + sizeText(loaded[0]) + "; all faces must be the same size";
            return false;
        }
    }
    faces = std::move(loaded);
    return true;
}

bool loadVolume(const std::string& path, Volume& out, std::string& error) {
    std::vector<std::uint8_t> bytes;
    if (!readFileBytes(path, bytes, error)) return false;
    Volume v;
    if (!decodeTex3D(bytes, v, error)) {
        error = path + ": " + error;
        return false;
    }
    out = std::move(v);
    return true;
}

}  // namespace glimmer
