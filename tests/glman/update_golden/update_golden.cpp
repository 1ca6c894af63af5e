// glimmer_update_golden [NAME...]: the one way to rewrite the Golden
// pictures (tests/data/glman/expected/NAME.png). Renders each script of
// golden_scripts.h (or only those named) on OSMesa exactly as
// Golden.MatchesTheStoredPicture does and writes the picture where its
// pixels changed, saying for each how far it moved. Run it through
// tools/update-golden.sh, then look at every picture it wrote before
// committing: the stored pictures are Glimmer's own output, checked by eye.
#include <cstdio>
#include <string>
#include <vector>

#include "glman_harness.h"
#include "golden_scripts.h"

using namespace glimmer;
using namespace glimmer::glmantest;

int main(int argc, char** argv) {
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        bool known = false;
        for (const char* g : kGoldenScripts) known |= argv[i] == std::string(g);
        if (!known) {
            std::fprintf(stderr, "glimmer_update_golden: '%s' is not one of the Golden scripts "
                                 "(tests/glman/golden_scripts.h)\n", argv[i]);
            return 2;
        }
        names.push_back(argv[i]);
    }
    if (names.empty()) names.assign(std::begin(kGoldenScripts), std::end(kGoldenScripts));
    int failed = 0, written = 0;
    for (const auto& name : names) {
        auto r = glimmer::testing::renderScript("osmesa", script(name), {}, {});
        if (!r.ok) {
            std::fprintf(stderr, "%s: cannot render it: %s\n", name.c_str(), r.error.c_str());
            ++failed;
            continue;
        }
        const std::string path = dataDir() + "/expected/" + name + ".png";
        Image before;
        std::string why;
        std::string said = "new";
        if (loadImage(path, before, why)) {
            auto d = glimmer::testing::compareRgb(r.screen, before);
            if (before.width == r.screen.width && before.height == r.screen.height && before.u8 == r.screen.u8) {
                std::printf("%s: unchanged\n", name.c_str());
                continue;
            }
            said = before.width != r.screen.width || before.height != r.screen.height
                       ? "another size"
                       : std::to_string(d.maxSteps) + " steps at most (at " + std::to_string(d.x) + ", " +
                             std::to_string(d.y) + "), " + std::to_string(d.pixelsOver1) +
                             " pixels differ by more than 1";
        }
        if (!writePng(path, r.screen, why)) {
            std::fprintf(stderr, "%s: %s\n", name.c_str(), why.c_str());
            ++failed;
            continue;
        }
        ++written;
        std::printf("%s: wrote %s (%s)\n", name.c_str(), path.c_str(), said.c_str());
    }
    std::printf("%d of %zu pictures rewritten%s\n", written, names.size(),
                written ? "; look at each before committing them" : "");
    return failed ? 1 : 0;
}
