// Which Clear steps nothing can see. A Clear followed, in the same pass, by
// a draw that paints every pixel of the target costs a full write of the
// target for nothing: the seed bloom's screen pass (Clear, then a quad over
// the whole screen) took twice as long as the same pass hand-written on the
// H100 (0.53 against 0.27 ms at 1920x1920), all of it the Clear. The plan
// marks such a Clear; the renderer skips it only when the covering draw's
// shaders also keep to the plain transform and never discard (what the
// plan cannot see: gl/renderer.cpp, shader/coverage_hints.h).
#pragma once
#include <glm/glm.hpp>

#include "plan/plan.h"

namespace glimmer {

// Whether `mesh` drawn with `clipFromObject` (projection * modelView) covers
// all of the viewport: a Quad (XY, XZ or YZ) whose four corners are in front
// of the eye and inside the depth range, and whose projection contains the
// four corners of the viewport. Every other shape: false (never assumed).
bool coversViewport(const MeshDecl& mesh, const glm::mat4& clipFromObject);

// Sets Step::hiddenBy on each Clear of a pass that draws no depth and writes
// at most one texture, to the index of a later step whose draw covers the
// viewport (-1 when none does).
void markHiddenClears(Plan& plan);

}  // namespace glimmer
