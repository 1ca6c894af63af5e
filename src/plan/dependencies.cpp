#include "plan/dependencies.h"

namespace glimmer {

std::set<int> programsOfPass(const Pass& pass) {
    std::set<int> out;
    for (const auto& s : pass.steps)
        if (s.kind == Step::Kind::Draw && s.draw.program >= 0) out.insert(s.draw.program);
    return out;
}

std::vector<bool> passesToRun(const Plan& plan, const Change& change) {
    std::vector<bool> run(plan.passes.size(), false);
    std::set<int> dirtyTextures = change.textures;
    bool screenDirty = false;
    // Passes run in script order, so a forward walk carries a change
    // downstream: a pass that runs again makes its targets dirty for the
    // passes after it. A target drawn by several passes holds all their
    // drawing, so when one of them runs they all must; that can reach back
    // to an earlier pass, hence the walk repeats until nothing new is marked.
    for (bool grew = true; grew;) {
        grew = false;
        for (size_t i = 0; i < plan.passes.size(); ++i) {
            const Pass& p = plan.passes[i];
            if (!p.needed || run[i]) continue;
            bool touched = change.everything;
            for (int prog : programsOfPass(p)) touched |= change.programs.count(prog) > 0;
            for (int t : p.reads) touched |= dirtyTextures.count(t) > 0;
            if (p.targets.empty()) touched |= screenDirty || change.screen;
            for (int t : p.targets) touched |= dirtyTextures.count(t) > 0;
            if (!touched) continue;
            run[i] = grew = true;
            dirtyTextures.insert(p.targets.begin(), p.targets.end());
            if (p.targets.empty()) screenDirty = true;
        }
    }
    return run;
}

std::vector<bool> passesFeeding(const Plan& plan, int pass) {
    std::vector<bool> feeds(plan.passes.size(), false);
    if (pass < 0 || size_t(pass) >= plan.passes.size()) return feeds;
    // A backward walk: a pass feeds the watched one when it writes a texture
    // that is read later on the way there; what it reads is then needed too.
    std::set<int> wanted = plan.passes[size_t(pass)].reads;
    for (size_t i = size_t(pass); i-- > 0;) {
        const Pass& p = plan.passes[i];
        bool writesWanted = false;
        for (int t : p.targets) writesWanted |= wanted.count(t) > 0;
        if (!writesWanted) continue;
        feeds[i] = true;
        wanted.insert(p.reads.begin(), p.reads.end());
    }
    return feeds;
}

}  // namespace glimmer
