// Which passes a change touches. A pass must run again when a uniform of a
// Program it draws with changed, when a texture it reads changed, or when a
// pass before it that it reads from ran again. Everything else keeps the
// picture it made last time.
#pragma once
#include <set>
#include <vector>

#include "plan/plan.h"

namespace glimmer {

struct Change {
    std::set<int> programs;  // programs whose uniforms changed (indices into Plan::programs)
    std::set<int> textures;  // textures whose contents changed outside any pass (an image reloaded)
    bool everything = false; // a reload, a resize: every needed pass
    bool screen = false;     // the view of the screen changed (mouse rotate, zoom)
};

// One flag per pass: true for a needed pass the change reaches, directly or
// downstream through the textures it writes.
std::vector<bool> passesToRun(const Plan& plan, const Change& change);

// One flag per pass: the passes before `pass` whose drawing it reads,
// directly or through another such pass (what a watch of `pass` must draw
// first: pipeline/watch.h). A pass that only draws under `pass` on the same
// target is not among them: the watch draws `pass` alone.
std::vector<bool> passesFeeding(const Plan& plan, int pass);

// The programs each pass draws with.
std::set<int> programsOfPass(const Pass& pass);

}  // namespace glimmer
