// The viewer with no platform in it (issue 25): what `glimmer view` and the
// page both are, once. A shell (view/viewer.cpp: GLFW; web/web_view.cpp:
// Emscripten) makes the context, turns its events into these calls and
// presents the picture; everything a student sees happen to the picture
// happens here, the same way in both:
//
//   load       prepare the script on a renderer of its own; on errors the
//              last good script, picture and slider values stay (adoptScript)
//   draw       the passes that changed, a slice of about `budgetMs` at a
//              time (gl/renderer_sliced.cpp), so a heavy blur never holds
//              the window or the page's input; a new script's first picture
//              whole
//   finished   the picture once every slice is drawn (Save, snapshots)
//   hardcopy   the script at another size with the values carried over
//   probe      the float value of every channel under a point of the picture
//   values     "Show values": the controls' values in a box over the
//              picture's top left, the same pixels in the window, the page
//              and a saved PNG
//   watch      one expression's value over its pass instead of the picture
//              (pipeline/watch.h), drawn again whole as sliders move, set up
//              again on every reload; the probe then reads its floats
//
// Contract: no GLFW, no Emscripten, no OpenGL calls of its own (the Renderer
// makes them); Dear ImGui only for the probe's tooltip and the values box. One core per shown
// script; the shell owns the context and keeps it current.
#pragma once
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pipeline/prepare_script.h"
#include "view/view_commands.h"
#include "view/view_model.h"
#include "view/viewer_state.h"

namespace glimmer {
class UiTexture;
}

namespace glimmer {

// Where the script comes from and how it is prepared: the same for every
// load and hardcopy.
struct ViewerSource {
    std::string script;
    std::vector<std::string> includeDirs;
    std::vector<std::string> sets;  // --set, applied to every load's first values
    bool standIns = true;           // a missing image or model becomes a stand-in, said in a warning
    bool sandbox = false;
};

// A slice of a heavy frame draws for about this long between two window
// frames: with the window's own ~10 ms on llvmpipe a frame stays near 35 ms
// while a slider is dragged (the goal is a p95 under 50 ms), and the bands
// stay tall enough that their set-up costs little (docs/PERFORMANCE.md).
// Once input has stopped, slices kIdleSliceFactor times longer bring the
// final picture sooner (fewer bands and frames between them).
constexpr double kSliceMs = 18;
constexpr double kIdleSliceFactor = 5;
// The "Show values" box's top left, in the picture and in the window.
constexpr int kOverlayAt = 8;
// The slice budget: kSliceMs, or $GLIMMER_SLICE_MS for benchmarks
// (tools/bench-viewer.sh), where 0 draws every frame whole, as before slices.
double sliceBudgetMs();

class ViewerCore {
public:
    using Clock = std::chrono::steady_clock;
    ViewerCore(ViewerSource source, GetProcAddress getProc);
    ~ViewerCore();
    // Lets go of every GL object (the renderer, the values box's texture):
    // the shell calls it while its context is still current.
    void releaseGl();

    ViewerState& state() { return s_; }
    const ViewerState& state() const { return s_; }
    const ViewerSource& source() const { return source_; }
    // The --set values the next loads start from (the page's ?set=).
    void setSets(std::vector<std::string> sets) { source_.sets = std::move(sets); }

    // Loads the script at w x h. True when it is on show now; false (its
    // errors kept in the state for the panel) when the last good script,
    // if any, stays. `diags` and `sources` receive what the load said.
    bool load(int w, int h, Diagnostics& diags, SourceTexts& sources, Plan* plan = nullptr);

    // Draws: starts a frame of the passes that changed since the last one
    // started (a change while a frame is under way replaces it and keeps
    // its unfinished passes), then about `budgetMs` of it. A new script's
    // first frame is drawn whole. True when a picture was finished.
    bool draw(double budgetMs);
    bool drawing() const { return drawing_.has_value(); }
    // The finished picture of what is shown (the screen or the inspected
    // target): any frame under way is drawn to its end first.
    Image finishedPicture();
    // glman's hardcopy: the script at w x h on a renderer of its own.
    Image renderAtSize(int w, int h);
    // What Save writes: the finished picture (or the hardcopy at
    // s.hardcopy's size), with the values box laid over it when "Show
    // values" is on, so a handout records its own parameters.
    Image savedPicture(bool hardcopy);

    // "Show values": the box as a layer (image/ttf_text.h labelLayer) in
    // DejaVu at the panel's text size times `scale` (the shell's ui scale:
    // legible from the back of a room at 2), remade only when its text
    // changes; empty when off or nothing to show. drawValues() puts it over
    // the picture (at kOverlayAt of the window) with Dear ImGui.
    void setUiScale(float scale) { uiScale_ = scale; }
    const Image& valuesLayer();
    void drawValues();

    // A command of the panel, --exec, standard input or the page that
    // changes only what is shown (set, show, values, probe, split): applied,
    // with what to tell the user in `said` ("" when nothing); false for the
    // shell's own (reload, save, scale, help, frames, quit). `probe X Y`
    // reads that pixel of the finished picture.
    bool apply(const ViewCommand& c, std::string& said);

    // The probe: the values under (x, y) of a picture shown in a pw x ph
    // rectangle (fitted, centred), in s.probeText; "" when off or outside.
    // Read back once per new picture. Shows it as a tooltip when `tooltip`.
    const std::string& probe(double x, double y, int pw, int ph, bool tooltip = true);

    // The passes started since the last call (a slider reaches only the
    // passes after it), by index.
    std::set<int> takeDrawnPasses();

    // For `frames` and the benchmarks: the last picture's wall time from
    // its first slice, and how many slices it took.
    double lastPictureMs() const { return lastPictureMs_; }
    int lastPictureSlices() const { return lastPictureSlices_; }
    std::uint64_t pictureVersion() const { return pictureVersion_; }
    // A frame of the window or page shown: the time since the last one is
    // kept while busy (a pause of a second or more is idle time, not a slow
    // frame). frameStats(): the `frames` line since the last call, how long
    // the window took between frames (what a drag feels like) and the last
    // picture's time after its last change; tools/bench-viewer.sh reads it.
    void noteFrame();
    std::string frameStats();
    Clock::time_point lastFrameShown() const { return lastUiFrame_; }

private:
    // The texture on `unit` (the screen for -1) into `texture`; false, with
    // `said`, when no target is on that unit.
    bool textureOnUnit(const char* command, int unit, int& texture, std::string& said) const;
    bool prepareAt(int w, int h, LoadedScript& next, std::unique_ptr<Renderer>& renderer, Diagnostics& diags);
    // `watch` commands (FILE:LINE EXPR, off, range): s_.watch and its picture.
    void applyWatch(const ViewCommand& c, std::string& said);
    // Sets up s_.watchSpec on the renderer now shown; false, with the
    // refusal in s_.watchError and `said`, when it cannot be watched.
    bool startWatchNow(std::string& said);
    // Draws the watch again when what it shows changed; true when it did.
    bool drawWatchFrame();
    // The picture the probe reads (the screen or the shown target, floats
    // where it holds them), read back once per new picture; the probe's
    // text for its pixel (ix, iy), "" outside it.
    const Image& probeImage();
    std::string probeTextAt(int ix, int iy);

    ViewerSource source_;
    GetProcAddress getProc_;
    ViewerState s_;
    std::optional<SlicedFrame> drawing_;  // the frame being drawn a slice at a time
    bool firstFrame_ = true;              // the next frame is a new renderer's first: drawn whole
    std::set<int> drawnPasses_;
    Clock::time_point drawingSince_{}, lastUiFrame_{};
    std::vector<double> frameIntervals_;  // ms between frames shown while busy
    int slices_ = 0, lastPictureSlices_ = 0;
    double lastPictureMs_ = 0;
    std::uint64_t pictureVersion_ = 0, probeVersion_ = ~0ull;
    int probeTexture_ = -2;
    Image probeImage_;
    std::unique_ptr<UiTexture> valuesTexture_;  // the values box, uploaded for Dear ImGui
    Image valuesLayer_;
    std::string valuesMadeFor_, valuesUploaded_;
    unsigned valuesId_ = 0;
    float uiScale_ = 1.f;
    WatchFrame watchFrame_;                 // the last watch drawn
    // The watch's value at the probed pixel, read from the GPU once per
    // pixel and picture (the probe asks every frame the pointer rests).
    struct WatchProbe {
        int x = -1, y = -1;
        std::uint64_t version = ~0ull;
        std::string text;
    } watchProbe_;
    std::optional<WatchRange> watchRange_;  // `watch range LO,HI`; none: the values' own
    bool watchStale_ = false;               // a watch set up or its range changed: draw it again
};

}  // namespace glimmer
