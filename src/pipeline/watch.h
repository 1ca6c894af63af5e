// A watch, from what the user typed to what is drawn, the same for every
// front end (render --watch, check --watch, the viewer's field and command,
// the page's editor):
//
//   FILE:LINE:EXPR -> the script's shader stage it names and the pass that
//     draws with that program (the last such pass)
//   -> the stage rewritten (shader/watch_rewrite.h; a vertex watch rewrites
//     the program's fragment stage too) -> built on the renderer (prepareWatch)
//   -> drawn: the passes that feed it, then it, into float targets
//     (Renderer::renderWatch) -> counted and coloured on the GPU
//     (gl/watch_gpu.cpp; what they mean: pipeline/watch_picture.h), the
//     floats read back only when asked for
//
// Every refusal is a diagnostic, at the watched line where there is one:
// file:line:col: error: ..., with the reason in the user's terms (not in
// scope there, a matrix, outside any function) rather than the rewrite's.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gl/renderer.h"
#include "pipeline/watch_picture.h"
#include "plan/plan.h"
#include "shader/watch_rewrite.h"

namespace glimmer {

struct Watch {
    WatchSpec spec;
    int program = -1;   // index into Plan::programs
    size_t stage = 0;   // index into its stages
    bool vertex = false;
    int pass = -1;      // the pass drawn into float targets
    std::string path;   // the stage's file, as diagnostics name it
    std::vector<bool> feeding;  // the passes drawn before it (plan/dependencies.h)
    std::optional<WatchRange> range;  // fixed (--watch-range), else the values' own
};

// Finds, rewrites and builds the watch on `renderer`, which holds `plan`
// prepared. False with diagnostics; the renderer then keeps no watch.
bool startWatch(const WatchSpec& spec, const Plan& plan, Renderer& renderer, Diagnostics& diags, Watch& out);

struct WatchFrame {
    bool drawn = false;  // false when the driver cannot draw into float targets
    WatchStats stats;
    // The picture is in the renderer's texture Renderer::kWatchPicture;
    // Renderer::readWatchPicture and readWatchCapture read it and the floats back.
};
// Draws the watch and counts and colours it on the GPU.
// `feeding`: the passes to draw first, when not all of watch.feeding need
// it (a viewer after a change that reaches only some of them).
WatchFrame drawWatch(Renderer& renderer, const Watch& watch, const UniformValues& values, double time,
                     const std::vector<bool>* feeding = nullptr);

// The exact value at pixel x, y (row 0 at the top) of the watch last
// drawn, as pipeline/watch_picture.h's watchValueAt says it.
std::string watchValueAt(const Renderer& renderer, int x, int y);

// "bloom.frag:12 rgbblur, pass 2 (Program Bloom)": what a front end shows
// beside the picture.
std::string watchTitle(const Watch& watch, const Plan& plan);

// LO,HI (two finite numbers, LO < HI) for --watch-range and the viewer.
bool parseWatchRange(const std::string& text, WatchRange& out, std::string& why);

}  // namespace glimmer
