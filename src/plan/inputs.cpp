#include "plan/inputs.h"

#include <set>

namespace glimmer {

std::vector<PlanInput> inputsOf(const Plan& plan) {
    std::vector<PlanInput> out;
    std::set<std::string> seen;
    auto add = [&](const std::string& path, const std::string& shown) {
        if (!path.empty() && seen.insert(path).second) out.push_back({path, shown.empty() ? path : shown});
    };
    add(plan.scriptFile, plan.scriptFile);
    for (const auto& t : plan.textures) {
        add(t.path, t.shown);
        for (size_t k = 0; k < t.facePaths.size(); ++k)
            add(t.facePaths[k], k < t.faceShown.size() ? t.faceShown[k] : t.facePaths[k]);
    }
    for (const auto& p : plan.programs)
        for (const auto& stage : p.stages) add(stage.path, stage.shown);
    for (const auto& m : plan.meshes) add(m.path, m.path);
    return out;
}

}  // namespace glimmer
