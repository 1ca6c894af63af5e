// The one place that issues GL calls for a script. Every front end (render,
// check, view, bench) drives a Renderer; every backend only hands it a
// function that finds GL entry points. It owns every GL object it makes.
#pragma once
#include <array>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/proc_address.h"
#include "gl/unset_uniform.h"
#include "image/image.h"
#include "lang/diagnostics.h"
#include "plan/plan.h"
#include "plan/uniform_values.h"

namespace glimmer {

struct Assets;
struct GlApi;

struct PassTiming {
    int pass = -1;      // index into Plan::passes
    double ms = 0;      // GPU time of the pass (timer query), or on a CPU renderer the wall
                        // clock around it with glFinish on each side
};

// A frame drawn a band of rows at a time, for a front end that must keep
// answering while a heavy pass draws (the viewer: a 23x23 superblur takes
// 0.6 s on llvmpipe). Each band is the pass's own draws under a scissor; a
// fragment's inputs do not depend on the scissor, so the finished frame
// holds exactly the pixels render() gives. Made by Renderer::startFrame,
// advanced by Renderer::renderSlice; drop it to abandon the frame.
struct SlicedFrame {
    explicit SlicedFrame(const UniformValues& v) : values(v) {}
    std::vector<bool> only;  // passes to draw (as render()'s `only`)
    UniformValues values;    // a copy: sliders may move while the frame draws
    double time = 0;
    std::size_t pass = 0;    // the pass being drawn
    int row = 0;             // the next band's first row in that pass (GL rows, from the bottom)
    double passMs = 0;       // time spent on that pass so far
    std::vector<PassTiming> timings;  // each finished pass, the sum of its bands
    bool done = false;
    mutable double progressShown = 0;  // progress() never goes back, though its weights are re-measured
    // The passes still to draw, the one under way included: a newer frame
    // that replaces this one must draw them too.
    std::vector<bool> unfinished() const;
};

// What a watch drew (pipeline/watch.h): one expression's value at every
// pixel of one pass, read back as floats, never through an 8-bit colour.
struct WatchCapture {
    Image value;  // RGBA float, row 0 at the top: the expression widened to a vec4
    // RGBA float: x 1 where a fragment ran, y the value's component count
    // there (0: the watched line did not run there), z its kind (WatchKind
    // in shader/watch_rewrite.h).
    Image info;
};

// What a watch's floats hold, counted on the GPU without reading them back
// (gl/watch_gpu.cpp): the numbers pipeline/watch_picture.h's watchStats
// computes on the CPU from a WatchCapture, which the tests hold these to.
struct WatchSums {
    int width = 0, height = 0;
    std::array<float, 4> lo{}, hi{};  // per component over its finite values; lo > hi: it has none
    long long drawn = 0, reached = 0, nan = 0, inf = 0, below = 0, above = 0;
    int components = 0, kind = 0;  // the most components seen, the largest kind
};

class Renderer {
public:
    // Loads the GL table through `getProc`; null and `error` when the driver
    // lacks what Glimmer needs. The context must be current.
    static std::unique_ptr<Renderer> create(const GetProcAddress& getProc, std::string& error);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // A watch: `program` built again with the stages in `replaced` (stage
    // index -> text; shader/watch_rewrite.h) in place of those prepare()
    // compiled. False, with the compiler's messages, when it does not build;
    // no watch is then kept. Dropped by the next prepare().
    bool prepareWatch(int program, const std::map<size_t, std::string>& replaced, Diagnostics& diags);
    void dropWatch();
    // Draws the passes flagged in `feeding` as render() does, then `pass`
    // into the watch's two float targets of its size, which stay on the GPU
    // for the calls below: the watched program's draws with the watch's
    // program, every other draw with colour writes off (it still hides what
    // lies behind it). False without a watch, or when the driver cannot
    // draw into float targets.
    bool renderWatch(int pass, const UniformValues& values, double time, const std::vector<bool>& feeding);
    // The drawn watch counted on the GPU (reductions; only a few hundred
    // bytes come back): a pixel counts as below or above when a component
    // is under `lo` or over `hi`. Empty when nothing is drawn.
    std::optional<WatchSums> sumWatch(float lo, float hi);
    // The watch's picture (pipeline/watch_picture.h says what it shows) drawn
    // on the GPU into texture kWatchPicture, with the range lo..hi, its
    // scale (t = (v - lo) x scale; 0: mid grey) and the six marker colours
    // (NaN, Inf, below, above, not run, not drawn).
    void colourWatch(float lo, float hi, float scale, const std::array<std::array<unsigned char, 3>, 6>& marks);
    // Read back when wanted: the picture colourWatch drew (RGBA8, row 0 at
    // the top), and the floats of the rectangle x, y, w x h (row 0 at the
    // top) of the drawn watch, or all of it. Empty when not drawn.
    Image readWatchPicture() const;
    WatchCapture readWatchCapture(int x = 0, int y = 0, int w = -1, int h = -1) const;
    // Each stage's text of `program` as prepare() compiled it (empty when it
    // was not built): what a watch rewrites.
    std::vector<std::optional<std::string>> programTexts(int program) const;

    // Waits until every GL command so far has run (for wall-clock timing):
    // glFinish on the desktop. In the browser WebGL's finish() only flushes
    // (Chromium runs the commands in its GPU process and does not wait), so
    // there it reads one pixel, a real round trip: of `texture` (a target,
    // through a framebuffer of its own) when one is given, else of the canvas.
    void finish(int texture = -1) const;
    std::string rendererName() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    // Whether pass timings come from GPU timer queries (a GPU) rather than
    // glFinish and a wall clock (a CPU renderer, where the queries mean nothing).
    bool gpuTimers() const;

    // Uploads what the CPU load step read (images, meshes; see
    // assets/assets.h), compiles and links programs, makes targets: only what
    // `assets.used` marks. Returns false when diags got errors; the renderer
    // then draws nothing. Front ends reach this through pipeline/prepare_script.h.
    bool prepare(const Plan& plan, const Assets& assets, Diagnostics& diags, bool everything = false);
    // The last prepare's steps and the wall clock of each, in ms (glimmer-bench).
    const std::vector<std::pair<std::string, double>>& prepareSteps() const { return prepareSteps_; }

    // Draws every needed pass with these uniform values, or only the passes
    // flagged in `only` (see plan/dependencies.h); the others keep what they
    // drew last time. `time` (seconds) drives the built-in Timer uniform.
    // With `timings`, each pass is timed.
    void render(const UniformValues& values, double time, std::vector<PassTiming>* timings = nullptr,
                const std::vector<bool>* only = nullptr);

    // A frame of the passes in `only` (see render()), to draw with renderSlice.
    SlicedFrame startFrame(const UniformValues& values, double time, std::vector<bool> only) const;
    // Draws bands of `frame` for about `budgetMs` of wall clock (at least one
    // band), each as tall as this pass's measured cost per row allows; true
    // when the frame is finished. A budget of infinity draws it all.
    bool renderSlice(SlicedFrame& frame, double budgetMs);
    // How much of the frame is drawn, 0 to 1, weighted by each pass's
    // measured cost; never less than it said before for this frame.
    double progress(const SlicedFrame& frame) const;

    // The texel-rate floor (gl/texel_rate.cpp): the fastest of `repeat` runs of
    // a hand-written full-screen pass fetching `taps` bilinear texels a
    // pixel from a width x height texture of `format` into a target of the
    // same, timed as render() times passes. -1 when the probe cannot run,
    // and at once (nothing built) outside 1..1024 taps, 1..16384 pixels each
    // way, or fewer than one repeat: the tap loop is unrolled by the driver.
    // It is drawn for `warmUp` of wall clock first (a GPU raises its clocks).
    double texelRateMs(int width, int height, TextureDecl::Format format, int taps, int repeat,
                       std::chrono::milliseconds warmUp = std::chrono::milliseconds(200));

    // Called with each pass's index as it starts; while one is set, each
    // pass is finished before the next starts, so the listener knows which
    // pass is drawing (--timeout names it; process/watchdog.h).
    void setPassListener(std::function<void(int pass)> listener) { passListener_ = std::move(listener); }

    // The watch's picture (colourWatch), shown by present and presentIn as
    // this texture.
    static constexpr int kWatchPicture = -2;

    // Copies the screen (texture -1) or a texture target to the window's
    // framebuffer 0, scaled to fit inside w x h and centred.
    void present(int texture, int windowWidth, int windowHeight) const;
    // The same into the rectangle x, y (top left, window pixels, y down), w x h
    // of a window `windowHeight` tall, fitted and centred in it; only the
    // columns from fraction u0 to u1 of the fitted picture are drawn (a
    // before/after split draws two textures side by side this way).
    void presentIn(int texture, int windowHeight, int x, int y, int w, int h, float u0 = 0.f, float u1 = 1.f) const;
    // The GL name of a render target's texture (the screen for -1), for ImGui's
    // own OpenGL backend to draw a thumbnail; 0 when it was not made.
    unsigned textureName(int texture) const;

    // What a linked program declares `name` as, for a slider of the right
    // kind; Unknown when the program was not built or does not use it.
    enum class UniformKind { Unknown, Float, Int, Bool, Sampler, Other };
    UniformKind uniformKind(int program, const std::string& name) const;
    // The uniforms its shaders read and the script never sets (they stay 0
    // until a value comes: the viewer's panel offers a control for each).
    std::vector<UnsetUniform> unsetUniforms(int program) const;
    // glman's mouse rotate and zoom: turns and scales everything drawn to the
    // screen about the world origin as seen by the eye. It goes into the
    // projection, so shaders see the script's own ModelView matrix.
    void setSceneTransform(const glm::mat4& m) { scene_ = m; }

    // How many built-in noise textures (Noise2, Noise3; one per resolution)
    // this renderer has made so far: only programs that declare them make them.
    std::size_t noiseTexturesMade() const { return noise2_.size() + noise3_.size(); }

    // Programs that read the built-in Timer uniform must redraw as time runs.
    bool usesTimer(int program) const;

    // The screen, row 0 at the top. RGBA8.
    Image readScreen() const;
    // Whether what was drawn and read so far can be trusted: "" or why not
    // (a GPU reset, a lost context, the driver out of memory; gl/gl_api.h's
    // contextFailure). batch's workers and render ask after every picture
    // (process/test_fault.h's pictureFailure). `refused`, when given, gets
    // the warning for a call the driver refused meanwhile (gl_api.h's
    // refusedCallWarning), or "".
    std::string contextFailure(std::string* refused = nullptr) const;
    // A texture of the plan (a render target or a loaded image), row 0 at the
    // top; empty if it was never made because nothing needed it.
    Image readTexture(int texture) const;
    // The same as float RGBA, for float targets, --dump to .hdr/.pfm and the
    // numeric health report. Empty if the texture was never made.
    Image readTextureFloat(int texture) const;
    // Whether a texture holds more than 8 bits a channel (a float target or a
    // float image): its --dump is read as float.
    bool isFloatTexture(int texture) const;
    // The textures the needed passes render into, in plan order.
    std::vector<int> renderTargets() const;

private:
    Renderer();
    struct Target;
    struct Program;
    struct MeshBuffers;
    void releaseAll();
    // The steps of prepare (renderer_prepare.cpp), in order.
    void uploadTextures(const Plan& plan, const Assets& assets);
    void uploadMeshes(const Plan& plan, const Assets& assets);
    void buildPrograms(const Plan& plan, const Assets& assets, Diagnostics& diags);
    // One Program from its stages' texts, and what it declares; null (with
    // the compiler's messages) when it does not build.
    std::unique_ptr<Program> makeProgram(const Plan& plan, const ProgramDecl& decl,
                                         const std::vector<std::optional<std::string>>& texts, Diagnostics& diags);
    // Samplers that read a unit holding another kind of texture (they read
    // black): warned on the Program line.
    void warnSamplerKinds(const Plan& plan, bool everything, Diagnostics& diags);
    // Shapes a program cannot draw (GL would refuse them with an error): warned, not drawn.
    void warnUndrawable(const Plan& plan, bool everything, Diagnostics& diags);
    // One framebuffer per distinct set of textures written at once.
    void makeTargets(const Plan& plan, bool everything, Diagnostics& diags);
    // The screen: an offscreen framebuffer of the output size, read back the same way on every backend.
    void makeScreen(const Plan& plan, Diagnostics& diags);
    // A depth renderbuffer of this size, attached to the bound framebuffer.
    unsigned attachDepth(int width, int height);
    // The pass's framebuffer (the screen's when it writes no texture).
    Target* passTarget(const Pass& pass) const;
    // Binds `target` for drawing into its first `colourBuffers` attachments,
    // over its whole size, with the depth test on (less) or off.
    void bindForPass(const Target& target, size_t colourBuffers, bool depth);
    // Binds the target and draws the pass's steps into it (under the scissor
    // when one is on); then, once the whole pass is drawn, finishPass remakes
    // the mip chains of the textures it wrote.
    void drawPass(const Pass& pass, Target* target, const UniformValues& values, double time);
    void finishPass(const Pass& pass);
    // A Clear the plan marked as covered (plan/hidden_clears.h) whose covering
    // draw will run and paint every pixel it covers: skipping it changes no pixel.
    bool clearIsHidden(const Pass& pass, const Step& clear, const Target* target) const;
    void drawStep(const Draw& d, const UniformValues& values, double time, const std::vector<int>& targets);
    // Why this mesh cannot be drawn with this program (a patch mesh without
    // tessellation shaders, a primitive the geometry shader does not take);
    // empty when it can.
    std::string drawProblem(const Program* prog, const MeshBuffers* mesh) const;
    // The built-in noise texture of this resolution, made on first use and
    // kept for the renderer's life.
    unsigned noiseTexture(bool threeD, int res);

    std::unique_ptr<GlApi> gl_;  // the loaded GL table (gl/gl_api.h), kept out of this header
    std::unique_ptr<Plan> plan_;  // a copy: the caller's plan may move (a viewer swapping scripts)
    struct TextureObject {
        unsigned id = 0;  // 0: not made, nothing needed it
        unsigned target = 0x0DE1;  // GL_TEXTURE_2D, GL_TEXTURE_3D or GL_TEXTURE_CUBE_MAP
        int width = 0, height = 0;
        TextureDecl::Format format = TextureDecl::Format::RGBA8;  // render targets; loaded images keep theirs
        bool mips = false;
        bool floatData = false;  // read back as float (float targets, .hdr and float .tex images)
    };
    std::vector<TextureObject> textures_;  // per TextureDecl
    std::vector<std::unique_ptr<MeshBuffers>> meshes_;
    std::vector<std::unique_ptr<Program>> programs_;
    std::vector<std::unique_ptr<Target>> targets_;
    std::unique_ptr<Program> watch_;  // the watched program, rewritten (prepareWatch)
    int watchedProgram_ = -1;         // which of programs_ it stands in for
    std::unique_ptr<Target> screen_;
    std::unique_ptr<Target> watchPicture_;  // colourWatch's picture
    unsigned watchPictureTexture_ = 0;
    // The watch's float targets and the GPU's programs that count and colour
    // them (gl/watch_gpu.cpp); the targets go with the watch, the programs
    // stay for the renderer's life.
    struct WatchGpu;
    std::unique_ptr<WatchGpu> watchGpu_;
    void dropWatchTargets();
    // The watch's float targets at this size (made again only when it
    // changes), bound for drawing; false when the driver cannot draw into them.
    bool bindWatchTargets(int width, int height, bool depth);
    glm::mat4 scene_{1.f};
    std::function<void(int)> passListener_;
    std::vector<std::pair<std::string, double>> prepareSteps_;
    std::vector<double> msPerRow_;  // per pass: the wall clock a row of it took in its last band (0: not yet)
    mutable int gpuTimers_ = -1;  // -1: not asked yet
    unsigned screenTexture_ = 0;
    // Noise2 (unit 2) and Noise3 (unit 3), per resolution; they outlive
    // prepare() so a reload does not make them again.
    std::map<int, unsigned> noise2_, noise3_;
};

}  // namespace glimmer
