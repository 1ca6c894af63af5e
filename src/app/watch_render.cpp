// glimmer render --watch: the value of one expression over its pass
// (pipeline/watch.h), written as a picture (.png) or as the floats
// themselves (.exr, .pfm, .hdr), with its range and counts on stdout.
#include <iostream>

#include <fmt/format.h>

#include "app/subcommands.h"
#include "pipeline/console.h"
#include "pipeline/watch.h"
#include "process/session.h"
#include "process/test_fault.h"

namespace glimmer {

namespace {

bool endsWith(const std::string& s, const char* tail) {
    std::string t(tail), lower = s;
    for (auto& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    return lower.size() >= t.size() && lower.compare(lower.size() - t.size(), t.size(), t) == 0;
}

}  // namespace

std::optional<int> checkWatchOptions(const RenderOptions& o) {
    if (o.watch.empty()) {
        if (!o.watchRange.empty()) {
            std::cerr << "glimmer: error: --watch-range needs --watch\n";
            return kExitUsage;
        }
        return std::nullopt;
    }
    if (o.frames != 1 || o.output == "-" || !o.dumps.empty()) {
        std::cerr << "glimmer: error: --watch writes one file: give -o a .png, .exr or .pfm, and no --frames or --dump\n";
        return kExitUsage;
    }
    if (!endsWith(o.output, ".png") && !endsWith(o.output, ".exr") && !endsWith(o.output, ".pfm") &&
        !endsWith(o.output, ".hdr")) {
        std::cerr << fmt::format("glimmer: error: --watch -o {}: write a .png (the picture) or .exr, .pfm, .hdr "
                                 "(the float values)\n", o.output);
        return kExitUsage;
    }
    return std::nullopt;
}

std::optional<int> startWatchOption(const std::string& text, Session& s, Watch& watch) {
    WatchSpec spec;
    std::string why;
    if (!parseWatchSpec(text, spec, why)) {
        std::cerr << "glimmer: error: --watch: " << why << "\n";
        return kExitUsage;
    }
    Diagnostics diags;
    if (!startWatch(spec, s.loaded.plan, *s.renderer, diags, watch)) {
        printDiagnostics(diags, s.loaded.sources, std::cerr);
        return kExitScriptError;
    }
    return std::nullopt;
}

int runRenderWatch(const RenderOptions& o, Session& s) {
    std::string why;
    WatchRange range;
    if (!o.watchRange.empty() && !parseWatchRange(o.watchRange, range, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitUsage;
    }
    Watch watch;
    if (auto code = startWatchOption(o.watch, s, watch)) return *code;
    if (!o.watchRange.empty()) watch.range = range;
    WatchFrame frame = drawWatch(*s.renderer, watch, *s.values, o.time);
    if (!frame.drawn) {
        std::cerr << "glimmer: error: --watch: the driver cannot draw into a float target (RGBA32F)\n";
        return kExitScriptError;
    }
    const bool floats = !endsWith(o.output, ".png");
    Image written = floats ? s.renderer->readWatchCapture().value : s.renderer->readWatchPicture();
    // As render's frames (render_command.cpp): what a lost or reset context
    // read back is not the script's, and its summary is not either.
    std::string refused;
    const std::string failure = pictureFailure(*s.renderer, o.script, written, &refused);
    if (!failure.empty()) {
        std::cerr << "glimmer: error: " << failure << "\n";
        return kExitScriptError;
    }
    printWarning(std::cerr, refused);
    if (!writeImage(o.output, written, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    std::cout << "watch " << watchTitle(watch, s.loaded.plan) << ": " << watchSummary(frame.stats) << "\n";
    reportWrote(fmt::format("{} ({}x{}, {})", o.output, written.width, written.height,
                            floats ? "the float values" : "the watch's picture"));
    return kExitOk;
}

}  // namespace glimmer
