// What a draw finds on a texture unit: OpenGL keeps one binding per target
// (2-D, 3-D, cube map) on each unit, and so does the plan (Draw::units holds
// the texture bound last, Draw::otherTargets those of other kinds still there).
#include "plan/plan.h"

namespace glimmer {

std::vector<int> Draw::texturesOn(int unit) const {
    std::vector<int> out;
    auto last = units.find(unit);
    if (last == units.end()) return out;
    out.push_back(last->second);
    if (auto others = otherTargets.find(unit); others != otherTargets.end())
        out.insert(out.end(), others->second.begin(), others->second.end());
    return out;
}

int Draw::textureOn(int unit, TextureDecl::Kind kind, const std::vector<TextureDecl>& textures) const {
    for (int t : texturesOn(unit))
        if (t >= 0 && size_t(t) < textures.size() && textures[size_t(t)].kind == kind) return t;
    return -1;
}

}  // namespace glimmer
