// The panel's watch section (issue 28): a field for FILE:LINE EXPR, Watch
// and Stop, a fixed range, what the watch shows (its summary and the marker
// colours) or why it was refused. It asks for `watch` commands, which the
// viewer core carries out (view/viewer_core.h), as for every other control.
#pragma once
#include <vector>

#include "view/viewer_state.h"

namespace glimmer {

void watchControls(ViewerState& s, std::vector<ViewCommand>& asked);

}  // namespace glimmer
