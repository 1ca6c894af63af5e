// The viewer with no platform in it (issue 25): what `glimmer view` and the
// page both are, once. A shell (view/viewer.cpp: GLFW; web/web_view.cpp:
// Emscripten) makes the context, hands the core its input and a ViewerHost
// for what only the platform does (save a file, print, reload, quit), and
// calls frame(); everything a student sees happen to the picture and the
// panel happens here, the same way in both (issue 38: each shell built the
// frame in its own words, and only the window measured numeric health):
//
//   load       prepare the script on a renderer of its own; on errors the
//              last good script, picture and slider values stay (adoptScript)
//   frame      one frame of the window or page: the passes that changed
//              (a slice of about `budgetMs`, gl/renderer_sliced.cpp, so a
//              heavy blur never holds the input; a new script's first
//              picture whole), numeric health now and then, the probe,
//              the panel, the values box, the picture and panel presented,
//              then what the panel and the keys asked, through the host
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
// Contract: no GLFW, no Emscripten, no OpenGL calls of its own (the Renderer,
// the WindowFrame and Dear ImGui's OpenGL 3 backend, the same in both shells,
// make them). The state is read-only to shells: they change it through the
// calls below. One core per shown script; the shell owns the context and
// keeps it current.
#pragma once
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pipeline/prepare_script.h"
#include "sheet/sheet_request.h"
#include "view/view_commands.h"
#include "view/view_keys.h"
#include "view/view_model.h"
#include "view/viewer_state.h"

namespace glimmer {
class UiTexture;
class WindowFrame;
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
    // The panel shows each message's first line only (the page: it shows
    // them whole under the canvas and marks them in its editor, so errors
    // never push the sliders out of a laptop's window, issue 27).
    bool oneLineMessages = false;
};

// What only the shell can do, asked by the core's frame and commands.
class ViewerHost {
public:
    virtual ~ViewerHost() = default;
    // The platform's part of a frame's start, between Dear ImGui's OpenGL 3
    // backend's NewFrame and ImGui::NewFrame: the platform backend's
    // NewFrame, or the page's display size and time step.
    virtual void platformFrame() {}
    // Input the frame reads once ImGui::NewFrame has taken its events (the
    // wheel, whether the panel has the pointer): the window's keys and mouse.
    virtual void input() {}
    // A line for the user: the window prints it after "glimmer view: " on
    // stderr, the page on the browser's console or as a command's answer.
    virtual void say(const std::string& line) = 0;
    // Text as it is: `frames` and `help` (toStdout), or the numeric-health
    // report once per change (stderr), for scripts that read them.
    virtual void print(const std::string& text, bool toStdout) = 0;
    virtual void reload() = 0;  // Reload, R, `reload`: the window loads again, the page asks its page
    // Save, S, `save [NAME]`: the picture (savedPicture) to NAME, or the
    // shell's own next name when "" (the page downloads it).
    virtual void save(const std::string& name, bool hardcopy) = 0;
    virtual void scale(float uiScale) = 0;  // `scale S`: the shell's layout, then setUiScale
    virtual void quit() = 0;                // Q, `quit`: the window closes; the page has no quit
};

// Where one frame puts things, in window (canvas) pixels, top-left origin.
struct FrameGeometry {
    int windowW = 0, windowH = 0;
    int pictureX = 0, pictureY = 0, pictureW = 0, pictureH = 0;
    float panelX = 0;     // the panel's left edge; it is as tall as the window
    float panelMaxW = 0;  // > 0: the panel is at most this wide (the page pins it)
    double budgetMs = 0;  // this frame's slice of drawing
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

    const ViewerState& state() const { return s_; }
    const ViewerSource& source() const { return source_; }
    // The --set values the next loads start from (the page's ?set=).
    void setSets(std::vector<std::string> sets) { source_.sets = std::move(sets); }

    // Loads the script at w x h. True when it is on show now; false (its
    // errors kept in the state for the panel) when the last good script,
    // if any, stays. `diags` and `sources` receive what the load said.
    // The panel's status line says `why` ("reloaded after a change to
    // bloom.frag"), or "WHY failed; keeping the last good picture".
    bool load(int w, int h, Diagnostics& diags, SourceTexts& sources, Plan* plan = nullptr,
              const std::string& why = "loaded");
    // The script and its shaders, as the last load that named them listed
    // them (what a student edits, in order); and every file any load read
    // (what the window watches: a broken edit keeps what it may still need).
    const std::vector<std::string>& scriptFiles() const { return scriptFiles_; }
    const std::vector<std::string>& readFiles() const { return readFiles_; }

    // The frame: false, with `why`, when the driver lacks what the window's
    // clear needs (made once, with the context current).
    bool startFrames(std::string& why);
    // One frame (see the head comment), the same steps in the window and
    // the page. The panel's size it measured: panelWidth(), panelHeight().
    void frame(const FrameGeometry& g, ViewerHost& host);
    int panelWidth() const { return panelW_; }
    int panelHeight() const { return panelH_; }
    // A command of the panel, --exec, standard input, a key or the page:
    // what the core does (apply), then the rest through the host.
    void command(const ViewCommand& c, ViewerHost& host);
    // A key (named as the DOM names it, view/view_keys.h) when no text field
    // has the keyboard: play/pause, the panel and the view reset now; reload,
    // save and quit at the end of the next frame. Returns its action (the
    // shell's own: Fullscreen) or None.
    KeyAction key(std::string_view name);
    // glman's mouse on the picture at px, py, pw, ph (view/viewer_state.h
    // pointerOnPicture); letGo: a button released anywhere.
    bool pointer(double x, double y, bool down, float wheel, bool captured, int px, int py, int pw, int ph);
    void letGo() { drag_.dragging = false; }
    // The time moves on by `seconds` while playing (a Timer's animation).
    void advance(double seconds);
    void setKeyHint(std::string hint) { s_.keyHint = std::move(hint); }
    void setStatus(std::string status) { s_.status = std::move(status); }
    // The numeric health (pipeline/numeric_health.h) of the last finished
    // picture, measured at most twice a second and not in a load's first
    // half second (it reads every target back); its report printed through
    // the host when it changes. `now`: measured whatever the time, if the
    // picture has not been (a save reads the picture back anyway; a quit
    // must not lose the report).
    void noteHealth(ViewerHost& host, bool now = false);

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
    // The panel's fonts are made again at the next frame's start (Dear
    // ImGui's font texture cannot change inside a frame).
    void setUiScale(float scale) { uiScale_ = scale; }
    float uiScale() const { return uiScale_; }
    const Image& valuesLayer();
    void drawValues();

    // A command of the panel, --exec, standard input or the page that
    // changes only what is shown (set, show, values, probe, split): applied,
    // with what to tell the user in `said` ("" when nothing); false for the
    // shell's own (reload, save, scale, help, frames, quit). `probe X Y`
    // reads that pixel of the finished picture.
    bool apply(const ViewCommand& c, std::string& said);
    // A control's value as --set's NAME=VALUE: true when it applied without
    // errors (the page's kept values after a reload).
    bool set(const std::string& assignment, Diagnostics& diags);
    // The contact sheet of the shown script at its values (Save sheet); the
    // next frame draws every pass again (the sheet drew over the targets).
    Image sheet(const SheetRequest& request);

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

    // The fonts at uiScale_ when the last frame's were made at another.
    void followUiScale(ViewerHost& host);
    void noteFiles(const Plan& plan);

    ViewerSource source_;
    GetProcAddress getProc_;
    ViewerState s_;
    std::unique_ptr<WindowFrame> windowFrame_;  // clears the window or canvas
    std::vector<ViewCommand> keyAsks_;           // reload, save, quit from keys: at the frame's end
    PictureDrag drag_;
    int panelW_ = 0, panelH_ = 0;
    std::vector<std::string> scriptFiles_, readFiles_;
    std::chrono::steady_clock::time_point lastHealth_{};
    std::uint64_t healthVersion_ = 0;
    std::string healthReport_;
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
    int loads_ = 0;                         // loads so far (the `panel` command says it: Reload's effect)
    bool pictureHashWanted_ = false;        // `panel` asked: hash the picture as the next frame shows it
    std::uint64_t pictureHash_ = 0;         // what `panel` says as picture= (WindowFrame::hashRegion)
};

}  // namespace glimmer
