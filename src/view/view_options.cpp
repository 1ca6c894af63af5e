// What `glimmer view` checks before it opens a window, and the window's
// first size: usage errors exit 2 before anything is shown.
#include <iostream>

#include <fmt/format.h>

#include "pipeline/load_script.h"
#include "pipeline/options.h"
#include "view/view_commands.h"
#include "view/viewer.h"

namespace glimmer {

int checkViewOptions(const ViewOptions& o, int& w, int& h) {
    w = h = 600;
    if (!o.size.empty() && !parseSize(o.size, w, h)) {
        std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT (1 to 16384 each)\n", o.size);
        return kExitUsage;
    }
    if (o.uiScale != 0 && !(o.uiScale >= 0.5 && o.uiScale <= 4)) {
        std::cerr << fmt::format("glimmer: error: --ui-scale {:g} is not between 0.5 and 4\n", o.uiScale);
        return kExitUsage;
    }
    for (const auto& line : splitCommands(o.exec)) {
        std::string error;
        if (!parseViewCommand(line, error) && !error.empty()) {
            std::cerr << "glimmer: error: --exec: " << error << "\n";
            return kExitUsage;
        }
    }
    // --size, else the script's WindowSize, else 600x600.
    if (!o.size.empty()) return 0;
    Diagnostics d;
    LoadedScript ls;
    if (loadScript(o.script, {}, d, ls)) {
        w = ls.plan.width;
        h = ls.plan.height;
    }
    return 0;
}

}  // namespace glimmer
