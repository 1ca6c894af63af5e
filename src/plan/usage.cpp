#include "plan/usage.h"

namespace glimmer {

Usage resourcesUsed(const Plan& plan, bool everything) {
    Usage u;
    u.textures.assign(plan.textures.size(), everything);
    u.meshes.assign(plan.meshes.size(), everything);
    u.programs.assign(plan.programs.size(), everything);
    for (const auto& pass : plan.passes) {
        if (!pass.needed && !everything) continue;
        for (int t : pass.targets) u.textures[size_t(t)] = true;
        for (int t : pass.reads) u.textures[size_t(t)] = true;
        for (const auto& s : pass.steps) {
            if (s.kind != Step::Kind::Draw) continue;
            u.meshes[size_t(s.draw.mesh)] = true;
            if (s.draw.program >= 0) u.programs[size_t(s.draw.program)] = true;
        }
    }
    return u;
}

}  // namespace glimmer
