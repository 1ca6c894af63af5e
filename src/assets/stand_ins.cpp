#include "assets/stand_ins.h"

#include <filesystem>

#include "image/noise.h"
#include "image/text.h"

namespace glimmer {

Image standInImage(const std::string& name, int size) {
    Image img = Image::rgba8(size, size);
    int cell = std::max(1, size / 8);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            bool odd = ((x / cell) + (y / cell)) % 2 == 1;
            std::uint8_t* p = &img.u8[(size_t(y) * size_t(size) + size_t(x)) * 4];
            p[0] = odd ? 128 : 255;
            p[1] = odd ? 128 : 0;
            p[2] = odd ? 128 : 255;
            p[3] = 255;
        }
    std::string label = "missing\n" + std::filesystem::path(name).filename().string();
    int scale = size >= 128 ? 2 : 1, w = 0, h = 0;
    measureText(label, scale, w, h);
    if (w <= size && h <= size) drawText(img, (size - w) / 2, (size - h) / 2, label, scale);
    return img;
}

bool needsStandIn(const TextureDecl& t) {
    if (t.source != TextureDecl::Source::File) return false;
    if (t.kind != TextureDecl::Kind::Cube) return t.path.empty();
    for (const auto& p : t.facePaths)
        if (p.empty()) return true;
    return false;
}

bool standInTexture(const TextureDecl& t, TextureFile& out, std::string& why) {
    if (t.kind == TextureDecl::Kind::Tex2D) {
        out.image = standInImage(t.shown);
    } else if (t.kind == TextureDecl::Kind::Tex3D) {
        out.volume = makeNoise3D(64);
    } else {
        int size = 0;
        for (size_t k = 0; k < 6 && k < t.facePaths.size(); ++k) {
            if (t.facePaths[k].empty()) continue;
            if (!loadImage(t.facePaths[k], out.faces[k], why)) return false;
            if (size && out.faces[k].width != size) {
                why = "cube map faces must all be square and of one size";
                return false;
            }
            size = out.faces[k].width;
        }
        for (size_t k = 0; k < 6 && k < t.facePaths.size(); ++k) {
            if (!t.facePaths[k].empty()) continue;
            out.faces[k] = standInImage(t.faceShown[k], size ? size : kStandInSize);
        }
    }
    out.loaded = true;
    return true;
}

bool needsStandIn(const MeshDecl& m) {
    return (m.shape == CommandKind::Obj || m.shape == CommandKind::ObjAdj || m.shape == CommandKind::WireObj) &&
           m.path.empty();
}

Mesh standInMesh(const MeshDecl& m) {
    // The plan sizes it to the view (plan/stand_in_size.h); a unit sphere otherwise.
    const float radius = m.params.empty() ? 1.f : float(m.params[0]);
    Mesh sphere = makeSphere(radius, 32, 16);
    if (m.shape == CommandKind::ObjAdj) return makeObjAdjacency(sphere);
    if (m.shape == CommandKind::WireObj) return makeWire(sphere);
    return sphere;
}

}  // namespace glimmer
