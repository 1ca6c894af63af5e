// The watch counted and coloured on the GPU (gl/watch_gpu.cpp) against the
// CPU's reference (pipeline/watch_picture.h) computed from the same floats
// read back: every statistic and every byte of the picture equal, for
// watches that have NaN, Inf, values outside a fixed range, pixels where the
// line did not run and pixels nothing drew, a vertex watch, ints and bools,
// at sizes that take one and two levels of the reduction and do not divide
// into its blocks.
#include <filesystem>
#include <fstream>
#include <set>
#include <string_view>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "backends/context.h"
#include "pipeline/watch_picture.h"
#include "pipeline/watch.h"
#include "gl/gl_api.h"
#include "render/render_harness.h"
#include "common/test_folder.h"

namespace glimmer {
namespace {
namespace fs = std::filesystem;

// Lines 6-8 run only left of x = 20; the quad covers the middle 60% of the
// screen, so the rest has no fragment at all.
const char* const kPartialFrag = R"(#version 330 compatibility
in vec2 vST;
void main( )
{
    vec4 c = vec4( vST, 0., 1. );
    if( gl_FragCoord.x < 20. ) {
        c.b = gl_FragCoord.y / 7. - 2.;
        int k = int( gl_FragCoord.y ) % 5;
    }
    gl_FragColor = c;
}
)";

const char* const kPartialGlib = R"(##OpenGL GLIB
Ortho -1 1 -1 1
LookAt 0 0 1  0 0 0  0 1 0
Vertex quad.vert
Fragment partial.frag
Program Partial
QuadXY 0 0.6
)";

struct Case {
    const char* script;  // in the test's folder
    const char* watch;
    int width, height;
    std::optional<WatchRange> range;
    const char* has;  // what the CPU's statistics must hold, so the case tests something
};

void expectSameStats(const WatchStats& gpu, const WatchStats& cpu) {
    EXPECT_EQ(gpu.width, cpu.width);
    EXPECT_EQ(gpu.height, cpu.height);
    EXPECT_EQ(gpu.components, cpu.components);
    EXPECT_EQ(gpu.kind, cpu.kind);
    for (size_t c = 0; c < 4; ++c) {
        EXPECT_EQ(gpu.lo[c], cpu.lo[c]) << "component " << c;
        EXPECT_EQ(gpu.hi[c], cpu.hi[c]) << "component " << c;
    }
    EXPECT_EQ(gpu.range.lo, cpu.range.lo);
    EXPECT_EQ(gpu.range.hi, cpu.range.hi);
    EXPECT_EQ(gpu.fixed, cpu.fixed);
    EXPECT_EQ(gpu.drawn, cpu.drawn);
    EXPECT_EQ(gpu.reached, cpu.reached);
    EXPECT_EQ(gpu.nan, cpu.nan);
    EXPECT_EQ(gpu.inf, cpu.inf);
    EXPECT_EQ(gpu.below, cpu.below);
    EXPECT_EQ(gpu.above, cpu.above);
    EXPECT_EQ(watchSummary(gpu), watchSummary(cpu));
}

using testing::makeRig;
using testing::Rig;

// The seed bloom (scripts/bloom.glib) loaded at size x size.
bool loadSeed(int size, Diagnostics& diags, LoadedScript& loaded) {
    PlanOptions options;
    options.width = options.height = size;
    return loadScript(std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib", options, diags, loaded);
}

TEST(WatchGpu, CountsAndPictureEqualTheCpuReferenceOnTheSameFloats) {
    testing::TestFolder dir("watch_gpu");
    const fs::path data = fs::path(GLIMMER_TEST_DATA) / "cli/watch";
    for (const char* f : {"calibration.glib", "calibration.frag", "quad.vert"})
        fs::copy_file(data / f, dir.path / f, fs::copy_options::overwrite_existing);
    std::ofstream(dir.path / "partial.frag") << kPartialFrag;
    std::ofstream(dir.path / "partial.glib") << kPartialGlib;

    const Case cases[] = {
        {"calibration.glib", "calibration.frag:10:exact", 37, 23, std::nullopt, "vec3"},
        {"calibration.glib", "calibration.frag:13:odd", 40, 40, std::nullopt, "nan inf"},
        {"calibration.glib", "calibration.frag:13:odd", 40, 40, WatchRange{30, 35}, "nan inf below above"},
        // 260 x 300: two levels of 16x16 blocks (17 x 19, then 2 x 2), neither dividing evenly; the
        // quad keeps its square shape, so rows above and below it are not drawn.
        {"calibration.glib", "calibration.frag:13:odd", 260, 300, WatchRange{100.1, 200.3}, "nan inf below above not-drawn"},
        {"calibration.glib", "calibration.frag:10:exact.xy * 0.001", 260, 300, WatchRange{-0.005, 0.7}, "below above"},
        {"calibration.glib", "quad.vert:10:vST", 53, 31, std::nullopt, "vec2"},
        {"calibration.glib", "quad.vert:10:vec4(vST, vST.x * vST.y, 1. - vST.y)", 53, 31, std::nullopt, "vec4"},
        {"partial.glib", "partial.frag:7:c", 64, 48, std::nullopt, "not-run not-drawn"},
        {"partial.glib", "partial.frag:8:k", 64, 48, std::nullopt, "int not-run"},
        {"partial.glib", "partial.frag:8:bvec3(k > 1, k > 2, true)", 64, 48, std::nullopt, "bool"},
        {"partial.glib", "partial.frag:8:uvec2(k, 7)", 64, 48, WatchRange{1, 6}, "below above"},
    };
    for (const std::string& backend : testing::testBackends()) {
        for (const Case& c : cases) {
            SCOPED_TRACE(backend + " " + c.script + " " + c.watch + " " + std::to_string(c.width) + "x" +
                         std::to_string(c.height));
            PlanOptions options;
            options.width = c.width, options.height = c.height;
            Diagnostics diags;
            LoadedScript loaded;
            ASSERT_TRUE(loadScript((dir.path / c.script).string(), options, diags, loaded));
            UniformValues values(loaded.plan);
            Rig rig = makeRig(backend, loaded, diags);
            ASSERT_TRUE(rig.renderer) << rig.error;
            Renderer* renderer = rig.renderer.get();
            std::string why;
            WatchSpec spec;
            ASSERT_TRUE(parseWatchSpec(c.watch, spec, why)) << why;
            Watch watch;
            ASSERT_TRUE(startWatch(spec, loaded.plan, *renderer, diags, watch));
            watch.range = c.range;
            WatchFrame frame = drawWatch(*renderer, watch, values, 0);
            ASSERT_TRUE(frame.drawn);

            const WatchCapture floats = renderer->readWatchCapture();
            ASSERT_EQ(floats.value.width, c.width);
            ASSERT_EQ(floats.value.height, c.height);
            const WatchStats cpu = watchStats(floats.value, floats.info, c.range);
            const std::string has = c.has;
            if (has.find("nan") != std::string::npos) { EXPECT_GT(cpu.nan, 0); }
            if (has.find("inf") != std::string::npos) { EXPECT_GT(cpu.inf, 0); }
            if (has.find("below") != std::string::npos) { EXPECT_GT(cpu.below, 0); }
            if (has.find("above") != std::string::npos) { EXPECT_GT(cpu.above, 0); }
            if (has.find("not-run") != std::string::npos) { EXPECT_LT(cpu.reached, cpu.drawn); }
            if (has.find("not-drawn") != std::string::npos) { EXPECT_LT(cpu.drawn, c.width * c.height); }
            if (has.find("vec2") != std::string::npos) { EXPECT_EQ(cpu.components, 2); }
            if (has.find("vec4") != std::string::npos) { EXPECT_EQ(cpu.components, 4); }
            if (has.find("int") != std::string::npos) { EXPECT_EQ(cpu.kind, 1); }
            if (has.find("bool") != std::string::npos) { EXPECT_EQ(cpu.kind, 3); }
            expectSameStats(frame.stats, cpu);

            const Image want = watchPicture(floats.value, floats.info, cpu);
            const Image got = renderer->readWatchPicture();
            ASSERT_EQ(got.width, want.width);
            ASSERT_EQ(got.height, want.height);
            long differ = 0, first = -1;
            for (size_t i = 0; i < want.u8.size() && i < got.u8.size(); ++i)
                if (want.u8[i] != got.u8[i]) {
                    ++differ;
                    if (first < 0) first = long(i);
                }
            EXPECT_EQ(differ, 0) << "first at pixel " << first / 4 % c.width << ", " << first / 4 / c.width
                                 << " channel " << first % 4;

            // One pixel read back alone is the same floats as the whole.
            const int px = c.width / 3, py = c.height / 2;
            const WatchCapture one = renderer->readWatchCapture(px, py, 1, 1);
            EXPECT_EQ(watchValueAt(one.value, one.info, 0, 0), watchValueAt(floats.value, floats.info, px, py));
            EXPECT_EQ(watchValueAt(*renderer, px, py), watchValueAt(floats.value, floats.info, px, py));
        }
    }
}

// Issue 40's sampled mutant watch_gpu.cpp:202 (deleting a third name past
// the watch's two): stopping a watch deletes its own textures and nothing of
// the script's. The seed, at sizes whose width is the name of one of its
// textures on a driver that numbers them from 1 (Mesa), draws after a watch
// is stopped exactly what it drew before the watch.
TEST(WatchGpu, StoppingAWatchLeavesTheScriptsTexturesAndItsPicture) {
    for (const std::string& backend : testing::testBackends()) {
        for (int size = 1; size <= 8; ++size) {
            SCOPED_TRACE(backend + " " + std::to_string(size) + "x" + std::to_string(size));
            Diagnostics diags;
            LoadedScript loaded;
            ASSERT_TRUE(loadSeed(size, diags, loaded));
            UniformValues values(loaded.plan);
            ASSERT_TRUE(values.applySet(loaded.plan, "uAdd=2", diags));
            Rig rig = makeRig(backend, loaded, diags);
            ASSERT_TRUE(rig.renderer) << rig.error;
            Renderer* renderer = rig.renderer.get();
            std::string why;
            renderer->render(values, 0.0);
            const Image before = renderer->readScreen();

            WatchSpec spec;
            ASSERT_TRUE(parseWatchSpec("bloom.frag:12:rgbblur", spec, why)) << why;
            Watch watch;
            ASSERT_TRUE(startWatch(spec, loaded.plan, *renderer, diags, watch));
            ASSERT_TRUE(drawWatch(*renderer, watch, values, 0).drawn);
            renderer->dropWatch();

            renderer->render(values, 0.0);
            const Image after = renderer->readScreen();
            ASSERT_EQ(after.width, before.width);
            EXPECT_EQ(after.u8, before.u8);
        }
    }
}

// A script of one pass in `dir`: a quad (the watch tests' quad.vert) drawn
// by Program `program` of `frag`, its sampler `sampler` set to `unit`, a
// unit the script gives no texture. The .glib's path.
fs::path quadWithSampler(const testing::TestFolder& dir, const std::string& program, const std::string& frag,
                         const std::string& sampler, int unit) {
    fs::copy_file(fs::path(GLIMMER_TEST_DATA) / "cli/watch/quad.vert", dir.path / "quad.vert",
                  fs::copy_options::overwrite_existing);
    std::ofstream(dir.path / (program + ".frag")) << frag;
    std::ofstream(dir.path / (program + ".glib")) << fmt::format(R"(##OpenGL GLIB
Ortho -1 1 -1 1
LookAt 0 0 1  0 0 0  0 1 0
Vertex quad.vert
Fragment {0}.frag
Program {0}
    {1} {2}
QuadXY 0 2
)", program, sampler, unit);
    return dir.path / (program + ".glib");
}

// Issue 40's sampled mutant watch_gpu.cpp:293 (the reduction's last merge
// unbinding three of the four units it bound): a watch leaves every unit as
// it found it, so a still scene watched frame after frame is the same watch.
// The script's program reads unit 3, which the script never gives a
// texture, as an unsigned sampler; at 260x300 the reduction takes two
// levels, and its merge binds its own unsigned counts to unit 3. Left there,
// the second frame's watched value would read them.
TEST(WatchGpu, AStillSceneWatchedTwiceIsTheSameWatch) {
    testing::TestFolder dir("watch_gpu_units");
    const fs::path script = quadWithSampler(dir, "stray", R"(#version 330 compatibility
uniform usampler2D uStray;
in vec2 vST;
void main( )
{
    uvec4 u = texture( uStray, vST );
    gl_FragColor = vec4( vec3( u.rgb ), 1. );
}
)", "uStray", 3);
    for (const std::string& backend : testing::testBackends()) {
        SCOPED_TRACE(backend);
        PlanOptions options;
        options.width = 260, options.height = 300;
        Diagnostics diags;
        LoadedScript loaded;
        ASSERT_TRUE(loadScript(script.string(), options, diags, loaded));
        UniformValues values(loaded.plan);
        Rig rig = makeRig(backend, loaded, diags);
        ASSERT_TRUE(rig.renderer) << rig.error;
        std::string why;
        WatchSpec spec;
        ASSERT_TRUE(parseWatchSpec("stray.frag:6:u", spec, why)) << why;
        Watch watch;
        ASSERT_TRUE(startWatch(spec, loaded.plan, *rig.renderer, diags, watch));
        const WatchFrame first = drawWatch(*rig.renderer, watch, values, 0);
        ASSERT_TRUE(first.drawn);
        const Image firstPicture = rig.renderer->readWatchPicture();
        // Nothing on the unit: every pixel reads the same.
        EXPECT_EQ(first.stats.lo, first.stats.hi);
        const WatchFrame second = drawWatch(*rig.renderer, watch, values, 0);
        ASSERT_TRUE(second.drawn);
        EXPECT_EQ(watchSummary(second.stats), watchSummary(first.stats));
        EXPECT_EQ(rig.renderer->readWatchPicture().u8, firstPicture.u8);
    }
}

// Issue 40's sampled mutant watch_gpu.cpp:222 (the watch's targets made from
// k = -1: the name before them, 0, was given an 8-bit image of the watch's
// size, so texture 0 was no longer empty). A watch changes no picture: a
// sampler on a unit the script gave no texture reads GL's (0, 0, 0, 1) for an
// empty texture before a watch, while it is drawn and after it stops.
TEST(WatchGpu, AWatchLeavesAUnitWithNoTextureEmpty) {
    testing::TestFolder dir("watch_gpu_empty_unit");
    const fs::path script = quadWithSampler(dir, "none", R"(#version 330 compatibility
uniform sampler2D uNone;
in vec2 vST;
void main( )
{
    vec4 t = texture( uNone, vST );
    gl_FragColor = vec4( t.a, t.r, 0.25, 1. );
}
)", "uNone", 5);
    for (const std::string& backend : testing::testBackends()) {
        SCOPED_TRACE(backend);
        PlanOptions options;
        options.width = options.height = 16;
        Diagnostics diags;
        LoadedScript loaded;
        ASSERT_TRUE(loadScript(script.string(), options, diags, loaded));
        UniformValues values(loaded.plan);
        Rig rig = makeRig(backend, loaded, diags);
        ASSERT_TRUE(rig.renderer) << rig.error;
        auto emptyEverywhere = [](const Image& picture) {
            int empty = 0;
            for (size_t p = 0; p + 3 < picture.u8.size(); p += 4)
                empty += picture.u8[p] == 255 && picture.u8[p + 1] == 0;  // t.a = 1, t.r = 0
            return empty;
        };
        rig.renderer->render(values, 0.0);
        const Image before = rig.renderer->readScreen();
        ASSERT_EQ(emptyEverywhere(before), 16 * 16);

        std::string why;
        WatchSpec spec;
        ASSERT_TRUE(parseWatchSpec("none.frag:6:t", spec, why)) << why;
        Watch watch;
        ASSERT_TRUE(startWatch(spec, loaded.plan, *rig.renderer, diags, watch));
        const WatchFrame frame = drawWatch(*rig.renderer, watch, values, 0);
        ASSERT_TRUE(frame.drawn);
        EXPECT_EQ(frame.stats.lo, frame.stats.hi);  // every pixel read the same
        rig.renderer->render(values, 0.0);
        EXPECT_EQ(emptyEverywhere(rig.renderer->readScreen()), 16 * 16) << "while watching";
        rig.renderer->dropWatch();
        rig.renderer->render(values, 0.0);
        EXPECT_EQ(rig.renderer->readScreen().u8, before.u8) << "after the watch stopped";
    }
}

// Issue 40's sampled mutant renderer.cpp:38 (the watch's three programs no
// longer deleted with their renderer). The page makes a new renderer on its
// one context for every picture (web/web_render.cpp): a watched lesson
// reloaded many times must not pile up programs on the student's GPU.
TEST(WatchGpu, ARendererMadeAgainOnOneContextLeavesNoProgramsBehind) {
    for (const std::string& backend : testing::testBackends()) {
        SCOPED_TRACE(backend);
        Diagnostics diags;
        LoadedScript loaded;
        ASSERT_TRUE(loadSeed(8, diags, loaded));
        UniformValues values(loaded.plan);
        Rig rig = makeRig(backend, loaded, diags);
        ASSERT_TRUE(rig.renderer) << rig.error;
        GlContext* context = rig.context.get();
        using IsProgram = unsigned char (*)(unsigned);
        auto isProgram = reinterpret_cast<IsProgram>(context->getProcAddress("glIsProgram"));
        ASSERT_NE(isProgram, nullptr);
        auto livePrograms = [&] {
            int live = 0;
            for (unsigned name = 1; name < 512; ++name) live += isProgram(name) ? 1 : 0;
            return live;
        };
        std::vector<int> live;
        for (int picture = 0; picture < 4; ++picture) {
            if (picture > 0) {  // as the page: the last renderer goes, a new one takes the context
                rig.renderer.reset();
                rig.renderer = Renderer::create([context](const char* n) { return context->getProcAddress(n); },
                                                rig.error);
                ASSERT_TRUE(rig.renderer) << rig.error;
                LoadedScript again;
                ASSERT_TRUE(loadSeed(8, diags, again));
                ASSERT_TRUE(loadAndUpload(*rig.renderer, again, false, diags));
                loaded = std::move(again);
            }
            std::string why;
            WatchSpec spec;
            ASSERT_TRUE(parseWatchSpec("bloom.frag:12:rgbblur", spec, why)) << why;
            Watch watch;
            ASSERT_TRUE(startWatch(spec, loaded.plan, *rig.renderer, diags, watch));
            ASSERT_TRUE(drawWatch(*rig.renderer, watch, values, 0).drawn);
            live.push_back(livePrograms());
        }
        EXPECT_EQ(live, std::vector<int>(4, live.front()));
    }
}

// The names of one kind of GL object the renderer holds, seen at its GL
// table: made by glGen*, given back by glDelete*. A name it deletes that
// it does not hold (never made as one, or deleted already) is stray: the
// driver may have given that name to another holder since (a texture or
// depth buffer of the script's, the panel's), whose object then goes.
using GenNames = void(GLAPIENTRY*)(GLsizei, GLuint*);
using DeleteNames = void(GLAPIENTRY*)(GLsizei, const GLuint*);
struct NamesSeen {
    GenNames driverGen = nullptr;
    DeleteNames driverDelete = nullptr;
    std::set<GLuint> held;
    std::vector<GLuint> stray;
};
NamesSeen renderbuffers, textures;
template <NamesSeen& seen>
void GLAPIENTRY genSeen(GLsizei n, GLuint* names) {
    seen.driverGen(n, names);
    seen.held.insert(names, names + n);
}
template <NamesSeen& seen>
void GLAPIENTRY deleteSeen(GLsizei n, const GLuint* names) {
    for (GLsizei k = 0; k < n; ++k)
        if (names[k] && !seen.held.erase(names[k])) seen.stray.push_back(names[k]);
    seen.driverDelete(n, names);
}
template <NamesSeen& seen>
void* seenAs(std::string_view name, std::string_view gen, std::string_view del, void* driver) {
    if (driver && name == gen) {
        seen.driverGen = reinterpret_cast<GenNames>(driver);
        return reinterpret_cast<void*>(&genSeen<seen>);
    }
    if (driver && name == del) {
        seen.driverDelete = reinterpret_cast<DeleteNames>(driver);
        return reinterpret_cast<void*>(&deleteSeen<seen>);
    }
    return nullptr;
}

// Issue 40's sampled mutants watch_gpu.cpp:220 (two framebuffer names made
// into a field of one, the second landing in the watch's depth buffer's
// name) and watch_gpu.cpp:208 (a stopped watch's float target's name kept,
// deleted again by the next stop or start): a watch started, stopped,
// started again and stopped deletes only names the renderer holds. The
// seed's watch on its screen pass, which has no depth.
TEST(WatchGpu, StoppingAWatchDeletesOnlyNamesItStillHolds) {
    for (const std::string& backend : testing::testBackends()) {
        SCOPED_TRACE(backend);
        Diagnostics diags;
        LoadedScript loaded;
        ASSERT_TRUE(loadSeed(8, diags, loaded));
        renderbuffers = {};
        textures = {};
        testing::Rig rig = testing::makeRig(backend, loaded, diags, [](std::string_view name, void* driver) {
            if (void* f = seenAs<renderbuffers>(name, "glGenRenderbuffers", "glDeleteRenderbuffers", driver)) return f;
            if (void* f = seenAs<textures>(name, "glGenTextures", "glDeleteTextures", driver)) return f;
            return driver;
        });
        ASSERT_TRUE(rig.renderer) << rig.error;
        Renderer* renderer = rig.renderer.get();
        UniformValues values(loaded.plan);
        std::string why;
        WatchSpec spec;
        ASSERT_TRUE(parseWatchSpec("bloom.frag:12:rgbblur", spec, why)) << why;
        for (int round = 0; round < 2; ++round) {
            Watch watch;
            ASSERT_TRUE(startWatch(spec, loaded.plan, *renderer, diags, watch));
            ASSERT_TRUE(drawWatch(*renderer, watch, values, 0).drawn);
            renderer->dropWatch();
        }
        for (GLuint name : renderbuffers.stray) ADD_FAILURE() << "renderbuffer " << name << " deleted, not held";
        for (GLuint name : textures.stray) ADD_FAILURE() << "texture " << name << " deleted, not held";
    }
}

}  // namespace
}  // namespace glimmer
