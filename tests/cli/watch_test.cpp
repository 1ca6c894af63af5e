// render --watch and check --watch (pipeline/watch.h), end to end: a watch of
// a value in 0..1 with range 0,1 is byte for byte the picture of the same
// shader hand-edited to write that value as its colour; the float file holds
// the values themselves; NaN and Inf are counted; refusals are exact.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A lesson's files copied into `dir` as the scripts find them: the seed's
// script with its shaders and picture beside it; the exercises' folder
// with ../../textures.
void copyLesson(const TempDir& dir) {
    const fs::path root = GLIMMER_SOURCE_DIR;
    fs::create_directories(dir.path() / "seed");
    fs::copy_file(root / "scripts/bloom.glib", dir.path() / "seed/bloom.glib");
    for (const char* f : {"bloom.vert", "bloom.frag", "superblur.vert", "superblur.frag"})
        fs::copy_file(root / "shaders" / f, dir.path() / "seed" / f);
    fs::copy_file(root / "textures/grid.bmp", dir.path() / "seed/grid.bmp");
    fs::create_directories(dir.path() / "scripts");
    fs::copy(root / "scripts/exercises", dir.path() / "scripts/exercises", fs::copy_options::recursive);
    fs::copy(root / "textures", dir.path() / "textures", fs::copy_options::recursive);
}

struct HandEdit {
    const char* script;  // in the copied lesson
    const char* shader;  // beside it
    int line;
    const char* expression;
    const char* colour;  // the expression widened to a vec3, as a student would write it
    int unit;            // the pass's target on this unit, or -1: the screen
    std::vector<std::string> sets;
};

// The shader with its colour line (the last gl_FragColor assignment)
// writing `colour` instead.
std::string handEdited(const std::string& text, const std::string& colour) {
    size_t at = text.rfind("gl_FragColor =");
    size_t end = at == std::string::npos ? at : text.find('\n', at);
    if (end == std::string::npos) {
        ADD_FAILURE() << "no colour line in:\n" << text;
        return text;
    }
    return text.substr(0, at) + "gl_FragColor = vec4( " + colour + ", 1. );" + text.substr(end);
}

TEST(CliWatch, AWatchInRangeZeroToOneEqualsTheHandEditedShaderByteForByte) {
    const HandEdit cases[] = {
        {"seed/bloom.glib", "bloom.frag", 11, "rgb", "rgb", -1, {}},
        {"seed/bloom.glib", "bloom.frag", 12, "rgbblur", "rgbblur", -1, {"uHalfSize=3"}},
        {"seed/bloom.glib", "bloom.frag", 12, "rgbblur.g", "vec3( rgbblur.g )", -1, {"uHalfSize=3"}},
        {"seed/bloom.glib", "bloom.frag", 12, "vST", "vec3( vST, 0. )", -1, {}},
        {"seed/bloom.glib", "bloom.frag", 12, "uAdd*rgbblur*0.25", "uAdd*rgbblur*0.25", -1, {"uAdd=3", "uHalfSize=3"}},
        {"seed/bloom.glib", "superblur.frag", 31, "rgbSum", "rgbSum", 6, {"uHalfSize=3"}},
        {"seed/bloom.glib", "superblur.frag", 16, "float(halfSize)/11.", "vec3( float(halfSize)/11. )", 6, {"uHalfSize=5"}},
        {"scripts/exercises/ex2_threshold.glib", "bright.frag", 13, "luminance", "vec3( luminance )", 6, {}},
        {"scripts/exercises/ex2_threshold.glib", "bright.frag", 13, "luminance > uThreshold ? c : vec3(0.)",
         "luminance > uThreshold ? c : vec3(0.)", 6, {"uThreshold=0.5"}},
        {"scripts/exercises/ex2_threshold.glib", "add.frag", 14, "blur", "blur", -1, {"uSigma=1"}},
        {"scripts/exercises/ex3_separable.glib", "gauss1d.frag", 18, "texel * 100.", "vec3( texel * 100., 0. )", 7, {}},
        {"scripts/exercises/ex5_hdr.glib", "tonemap.frag", 14, "mapped", "mapped", -1, {}},
    };
    for (const HandEdit& c : cases) {
        SCOPED_TRACE(std::string(c.shader) + ":" + std::to_string(c.line) + " " + c.expression);
        TempDir dir;
        copyLesson(dir);
        const std::string script = dir.file(c.script);
        const std::string shader = (fs::path(script).parent_path() / c.shader).string();
        std::vector<std::string> common = {"--backend", "osmesa", "--size", "96x96"};
        for (const auto& s : c.sets) common.insert(common.end(), {"--set", s});
        std::vector<std::string> watch = {"render", script, "-o", dir.file("watch.png"), "--watch-range", "0,1",
                                          "--watch", std::string(c.shader) + ":" + std::to_string(c.line) + ":" + c.expression};
        watch.insert(watch.end(), common.begin(), common.end());
        RunResult w = runGlimmer(watch);
        ASSERT_EQ(w.exitCode, 0) << w.err;
        EXPECT_EQ(countOf(w.out, "range 0 .. 1 (fixed)"), 1) << w.out;
        EXPECT_EQ(countOf(w.out, "outside"), 0) << w.out;

        const std::string edited = handEdited(readText(shader), c.colour);
        std::ofstream(shader, std::ios::binary) << edited;
        std::vector<std::string> hand = {"render", script, "-o", dir.file("hand.png")};
        if (c.unit >= 0) hand.insert(hand.end(), {"--dump", std::to_string(c.unit) + "=" + dir.file("unit.png")});
        hand.insert(hand.end(), common.begin(), common.end());
        RunResult h = runGlimmer(hand);
        ASSERT_EQ(h.exitCode, 0) << h.err;
        glimmer::Image a = loadPicture(dir.file("watch.png"));
        glimmer::Image b = loadPicture(c.unit >= 0 ? dir.file("unit.png") : dir.file("hand.png"));
        ASSERT_EQ(a.width, b.width);
        ASSERT_EQ(a.height, b.height);
        size_t differ = 0;
        for (size_t i = 0; i < a.u8.size() && i < b.u8.size(); ++i) differ += a.u8[i] != b.u8[i];
        EXPECT_EQ(differ, 0u) << "bytes differ";
        EXPECT_EQ(a.u8.size(), b.u8.size());
    }
}

// A PFM (RGB float, rows from the bottom): the pixels row 0 at the top.
std::vector<float> readPfm(const std::string& path, int& width, int& height) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    float scale = 0;
    in >> magic >> width >> height >> scale;
    in.get();
    std::vector<float> bottomUp(size_t(width) * size_t(height) * 3);
    in.read(reinterpret_cast<char*>(bottomUp.data()), std::streamsize(bottomUp.size() * sizeof(float)));
    if (magic != "PF" || !in) return {};
    std::vector<float> rows(bottomUp.size());
    const size_t row = size_t(width) * 3;
    for (int y = 0; y < height; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row), row, rows.begin() + std::ptrdiff_t(size_t(y) * row));
    return rows;
}

// `glimmer render` of the calibration scene at 40x40 with `extra`.
RunResult renderCalibration(const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", cliData("watch/calibration.glib"), "--backend", "osmesa", "--size", "40x40"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runGlimmer(args);
}

TEST(CliWatch, TheFloatFileHoldsTheValuesAsTheCpuComputesThem) {
    TempDir dir;
    RunResult r = renderCalibration({"--watch", "calibration.frag:10:exact", "-o", dir.file("exact.pfm")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "watch calibration.frag:10 exact, pass 1 (Program Calibration): vec3 over 40x40: range -9.875 .. "
                     "1560 (its own); x -9.875 .. -0.125, y 0.25 .. 1560, z 1000 .. 1040\n");
    int w = 0, h = 0;
    std::vector<float> px = readPfm(dir.file("exact.pfm"), w, h);
    ASSERT_EQ(w, 40);
    ASSERT_EQ(h, 40);
    ASSERT_EQ(px.size(), 40u * 40u * 3u);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // gl_FragCoord: the pixel's centre, y from the bottom.
            const float fx = float(x) + 0.5f, fy = float(h - 1 - y) + 0.5f;
            const float want[3] = {fx * 0.25f - 10.f, fx * fy, 1000.f + fy};
            for (int c = 0; c < 3; ++c) wrong += px[(size_t(y) * 40 + size_t(x)) * 3 + size_t(c)] != want[c];
        }
    EXPECT_EQ(wrong, 0);
}

TEST(CliWatch, NanAndInfAreCountedAndValuesOutsideAFixedRangeToo) {
    TempDir dir;
    RunResult r = renderCalibration({"--watch", "calibration.frag:13:odd", "-o", dir.file("odd.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "watch calibration.frag:13 odd, pass 1 (Program Calibration): float over 40x40: range 25.5 .. "
                     "39.5 (its own); 400 pixels NaN; 600 pixels Inf\n");
    r = renderCalibration({"--watch",
                    "calibration.frag:13:odd", "--watch-range", "30,35", "-o", dir.file("odd.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "watch calibration.frag:13 odd, pass 1 (Program Calibration): float over 40x40: range 30 .. 35 "
                     "(fixed); 400 pixels NaN; 600 pixels Inf; 200 pixels below the range; 200 pixels above the range\n");
    // The marks: magenta and black for NaN, yellow for Inf, a grey for a value.
    glimmer::Image p = loadPicture(dir.file("odd.png"));
    ASSERT_EQ(p.width, 40);
    auto at = [&](int x, int y) {
        const unsigned char* q = &p.u8[(size_t(y) * 40 + size_t(x)) * 4];
        return std::vector<int>{q[0], q[1], q[2]};
    };
    EXPECT_EQ(at(0, 0), (std::vector<int>{255, 0, 255}));
    EXPECT_EQ(at(4, 0), (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(at(16, 0), (std::vector<int>{255, 255, 0}));
    EXPECT_EQ(at(32, 0), (std::vector<int>{int(std::lround((32.5 - 30) / 5 * 255)), int(std::lround((32.5 - 30) / 5 * 255)),
                                           int(std::lround((32.5 - 30) / 5 * 255))}));
}

TEST(CliWatch, AVertexWatchShowsTheValueInterpolatedAcrossThePrimitive) {
    TempDir dir;
    RunResult r = renderCalibration({"--watch", "quad.vert:10:vST", "-o", dir.file("st.pfm")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.out, "watch quad.vert:10 vST, pass 1 (Program Calibration): vec2 over 40x40"), 1) << r.out;
    int w = 0, h = 0;
    std::vector<float> px = readPfm(dir.file("st.pfm"), w, h);
    ASSERT_EQ(px.size(), 40u * 40u * 3u);
    double worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // The quad's s and t run 0..1 over the screen: at a pixel's centre, (x + 0.5) / 40.
            const double s = (x + 0.5) / 40, t = (h - 1 - y + 0.5) / 40;
            worst = std::max({worst, std::abs(px[(size_t(y) * 40 + size_t(x)) * 3] - s),
                              std::abs(px[(size_t(y) * 40 + size_t(x)) * 3 + 1] - t)});
        }
    EXPECT_LT(worst, 1e-5) << "interpolated, not through 8 bits (1/255 apart)";
}

TEST(CliWatch, IntsUintsAndBoolsAreWatchedAndSaidAsWhatTheyAre) {
    const std::pair<const char*, const char*> cases[] = {
        {"superblur.frag:16:halfSize", "int over 512x512: range 5 .. 5 (its own)"},
        {"superblur.frag:10:ires", "ivec2 over 512x512: range 512 .. 512 (its own); x 512 .. 512, y 512 .. 512"},
        {"superblur.frag:16:uHalfSize > 3", "bool over 512x512: range 1 .. 1 (its own)"},
        {"superblur.frag:16:bvec2(uHalfSize > 9, uHalfSize > 3)",
         "bvec2 over 512x512: range 0 .. 1 (its own); x 0 .. 0, y 1 .. 1"},
        {"superblur.frag:16:uvec3(1u, 2u, 3u)", "uvec3 over 512x512: range 1 .. 3 (its own); x 1 .. 1, y 2 .. 2, z 3 .. 3"},
        // Every other overload of the capture (shader/watch_rewrite.cpp), each with its component
        // count and kind (issue 40: a scalar uint's count 0 and an ivec4's 5 passed every test).
        {"superblur.frag:16:uint(uHalfSize) + 2u", "uint over 512x512: range 7 .. 7 (its own)"},
        {"superblur.frag:16:ivec3(1, 2, 3)", "ivec3 over 512x512: range 1 .. 3 (its own); x 1 .. 1, y 2 .. 2, z 3 .. 3"},
        {"superblur.frag:16:ivec4(1, 2, 3, 4)",
         "ivec4 over 512x512: range 1 .. 4 (its own); x 1 .. 1, y 2 .. 2, z 3 .. 3, w 4 .. 4"},
        {"superblur.frag:16:uvec2(1u, 2u)", "uvec2 over 512x512: range 1 .. 2 (its own); x 1 .. 1, y 2 .. 2"},
        {"superblur.frag:16:uvec4(1u, 2u, 3u, 4u)",
         "uvec4 over 512x512: range 1 .. 4 (its own); x 1 .. 1, y 2 .. 2, z 3 .. 3, w 4 .. 4"},
        {"superblur.frag:16:bvec3(true, false, true)",
         "bvec3 over 512x512: range 0 .. 1 (its own); x 1 .. 1, y 0 .. 0, z 1 .. 1"},
        {"superblur.frag:16:bvec4(true, false, true, false)",
         "bvec4 over 512x512: range 0 .. 1 (its own); x 1 .. 1, y 0 .. 0, z 1 .. 1, w 0 .. 0"},
        {"superblur.frag:16:vec2(0.5, 2.)", "vec2 over 512x512: range 0.5 .. 2 (its own); x 0.5 .. 0.5, y 2 .. 2"},
        {"superblur.frag:16:vec4(1., 2., 3., 4.)",
         "vec4 over 512x512: range 1 .. 4 (its own); x 1 .. 1, y 2 .. 2, z 3 .. 3, w 4 .. 4"},
    };
    TempDir dir;
    for (const auto& [watch, said] : cases) {
        RunResult r = runGlimmer({"render", "scripts/bloom.glib", "--backend", "osmesa", "--set", "uHalfSize=5",
                                  "--watch", watch, "-o", dir.file("k.png")});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(countOf(r.out, std::string(": ") + said + "\n"), 1) << watch << ": " << r.out;
    }
}

TEST(CliWatch, ScopeLineAndTypeErrorsAreExact) {
    struct Case {
        const char* watch;
        std::string message;
    };
    const Case cases[] = {
        {"bloom.frag:11:rgbblur",
         "shaders/bloom.frag:11:51: error: 'rgbblur' is not in scope at line 11: watch a variable declared before this "
         "line in the same block or one around it, a uniform, or an input\n"
         "    vec3 rgb      = texture( ImageUnit, vST ).rgb;\n"
         "                                                  ^\n"},
        {"bloom.frag:12:mat2(rgbblur.rg, rgbblur.gb)",
         "shaders/bloom.frag:12:49: error: 'mat2(rgbblur.rg, rgbblur.gb)' is a mat2: a matrix cannot be watched; watch "
         "a column (mat2(rgbblur.rg, rgbblur.gb)[0]) or an element (mat2(rgbblur.rg, rgbblur.gb)[0][0])\n"},
        {"bloom.frag:5:uAdd",
         "shaders/bloom.frag:5:1: error: line 5 is outside any function: a watch goes on a line inside a function's "
         "body, such as main's\n"
         "uniform float uAdd;\n"
         "^\n"},
        {"bloom.frag:2:uAdd",
         "shaders/bloom.frag:2:1: error: line 2 holds no statement (it is blank, a comment or a directive): watch a "
         "line with one\n"},
        {"nothere.frag:2:uAdd",
         "scripts/bloom.glib: error: --watch: 'nothere.frag' is not a shader of this script (its shaders: "
         "superblur.vert, superblur.frag, bloom.vert, bloom.frag)\n"},
    };
    for (const Case& c : cases) {
        RunResult r = checkOnOsmesa("scripts/bloom.glib", {"--watch", c.watch});
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_EQ(countOf(r.err, c.message), 1) << "want:\n" << c.message << "got:\n" << r.err;
    }
    RunResult ok = checkOnOsmesa("scripts/bloom.glib", {"--watch", "bloom.frag:12:rgbblur"});
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_EQ(ok.out, "watch bloom.frag:12 rgbblur, pass 2 (Program Bloom): can be watched\n");
    RunResult usage = checkOnOsmesa("scripts/bloom.glib", {"--watch", "bloom.frag:rgbblur"});
    EXPECT_EQ(usage.exitCode, 2);
    EXPECT_EQ(countOf(usage.err, "glimmer: error: --watch: 'bloom.frag:rgbblur' is not FILE:LINE:EXPRESSION (for "
                                 "example bloom.frag:12:rgbblur)\n"), 1) << usage.err;
}

// render draws only the passes whose pictures reach the screen, and builds
// only their programs: a watch in a pass nothing reads is refused with the
// program named, not a crash (issue 40: a sampled mutant read the missing
// program's first shader past the end of an empty list).
TEST(CliWatch, AProgramWhosePictureNothingReadsIsRefusedAsNotBuilt) {
    TempDir dir;
    fs::copy_file(fs::path(GLIMMER_TEST_DATA) / "glman" / "pass.vert", dir.path() / "pass.vert");
    fs::copy_file(fs::path(GLIMMER_TEST_DATA) / "glman" / "pass.vert", dir.path() / "unread.vert");
    writeFile(dir, "unread.frag", "#version 330 compatibility\nin vec2 vST;\nvoid main() {\n"
                                  "    float r = vST.s;\n    gl_FragColor = vec4(r, 0., 0., 1.);\n}\n");
    writeFile(dir, "shown.frag", "#version 330 compatibility\nin vec2 vST;\n"
                                 "void main() { gl_FragColor = vec4(0., vST.t, 0., 1.); }\n");
    const std::string script = writeFile(dir, "unread.glib",
                                         "WindowSize 32 32\nOrtho -1 1 -1 1\nTexture2D 5 32 32\nRenderToTexture 5\n"
                                         "Vertex unread.vert\nFragment unread.frag\nProgram Unread\nQuadXY 0 1\n"
                                         "RenderToTexture\nVertex pass.vert\nFragment shown.frag\nProgram Shown\n"
                                         "QuadXY 0 1\n");
    for (const char* watch : {"unread.vert:7:vST", "unread.frag:4:r"}) {  // its first stage and its second
        RunResult r = runGlimmer({"render", script, "--backend", "osmesa", "--watch", watch, "-o", dir.file("w.png")});
        EXPECT_EQ(r.exitCode, 1) << watch << ": " << r.err;
        EXPECT_EQ(r.err, script + ":7:1: error: --watch: Program Unread was not built, so nothing can be watched in "
                                  "it\nProgram Unread\n^\n1 error, 0 warnings\n") << watch;
        EXPECT_FALSE(fs::exists(dir.file("w.png")));
    }
    // The shown pass's shader is watched as usual.
    RunResult ok = runGlimmer({"render", script, "--backend", "osmesa", "--watch", "shown.frag:3:vST.t", "-o",
                               dir.file("w.png")});
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
}

// A Program the script never draws with has no pixels: a watch in its shader
// is refused with that said, before anything else is asked of it.
TEST(CliWatch, AProgramThatDrawsNothingIsRefused) {
    TempDir dir;
    fs::copy_file(fs::path(GLIMMER_TEST_DATA) / "glman" / "pass.vert", dir.path() / "pass.vert");
    writeFile(dir, "idle.frag", "#version 330 compatibility\nin vec2 vST;\nvoid main() {\n"
                                "    float r = vST.s;\n    gl_FragColor = vec4(r, 0., 0., 1.);\n}\n");
    writeFile(dir, "shown.frag", "#version 330 compatibility\nin vec2 vST;\n"
                                 "void main() { gl_FragColor = vec4(0., vST.t, 0., 1.); }\n");
    const std::string script = writeFile(dir, "idle.glib", "WindowSize 32 32\nVertex pass.vert\nFragment idle.frag\n"
                                                           "Program Idle\nFragment shown.frag\nProgram Shown\nQuadXY 0 1\n");
    RunResult r = runGlimmer({"render", script, "--backend", "osmesa", "--watch", "idle.frag:4:r", "-o", dir.file("w.png")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, script + ":4:1: error: --watch: Program Idle draws nothing, so idle.frag has no pixels to watch\n"
                              "Program Idle\n^\n1 error, 0 warnings\n");
    EXPECT_FALSE(fs::exists(dir.file("w.png")));
}

// A range whose numbers do not read as finite doubles is refused, whole: a
// bound beyond a double's range (1e999) must not fall back to the value the
// range held before (issue 40: the number's parse error accepted, a sampled
// mutant no test caught).
TEST(CliWatch, ARangeWhoseBoundsAreNotFiniteNumbersIsRefused) {
    const std::string script = std::string(GLIMMER_SOURCE_DIR) + "/scripts/bloom.glib";
    TempDir dir;
    for (const char* range : {"0,1e999", "-1e999,1", "0,nan", "0,inf", "0,1x", "0 1", "1,0"}) {
        auto r = runGlimmer({"render", script, "-o", dir.file("x.png"), "--watch", "bloom.frag:12:rgbblur",
                             "--watch-range", range});
        EXPECT_EQ(r.exitCode, 2) << range << r.err;
        EXPECT_EQ(countOf(r.err, std::string("glimmer: error: --watch-range '") + range +
                                     "' is not LO,HI with LO less than HI (for example 0,1)\n"),
                  1)
            << range << r.err;
        EXPECT_FALSE(fs::exists(dir.file("x.png"))) << range;
    }
}

// s.glib in `dir`: one Program C (uAdd <0. 1. 4.>) of c.vert and c.frag,
// with those texts, on a quad over the screen.
void writeOneProgram(const TempDir& dir, const std::string& vert, const std::string& frag) {
    std::ofstream(dir.file("s.glib")) << "Ortho -1. 1. -1. 1.\nVertex c.vert\nFragment c.frag\n"
                                         "Program C uAdd <0. 1. 4.>\nQuadXY .2 2.\n";
    std::ofstream(dir.file("c.vert")) << vert;
    std::ofstream(dir.file("c.frag")) << frag;
}

// A directive's end is found by the GLSL lexer: a block comment opened on a
// '#define' line runs on to its "*/", even after a '/' of division on that
// line. Read wrong, the comment's second line becomes code and its '{'
// puts main's lines "outside any function" (issue 40: a sampled mutant of
// the "//" test no test caught).
TEST(CliWatch, ABlockCommentAfterADivisionInADefineEndsWhereItsStarSlashIs) {
    TempDir dir;
    writeOneProgram(dir,
                    "#version 120\nvarying vec2 vST;\nvoid main() { vST = gl_MultiTexCoord0.st; "
                    "gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n",
                    "#version 120\n"
                    "#define HALF(x) ((x)/2.) /* half of x; the comment goes on\n"
                    "   to a second line { and a brace */\n"
                    "uniform float uAdd;\nvarying vec2 vST;\nvoid main() {\n"
                    "    float h = HALF(uAdd);\n    gl_FragColor = vec4(h, vST, 1.);\n}\n");
    auto inMain = runGlimmer({"check", dir.file("s.glib"), "--watch", "c.frag:7:uAdd"});
    EXPECT_EQ(inMain.exitCode, 0) << inMain.err;
    EXPECT_EQ(inMain.out, "watch c.frag:7 uAdd, pass 1 (Program C): can be watched\n") << inMain.err;
    auto inComment = runGlimmer({"check", dir.file("s.glib"), "--watch", "c.frag:3:uAdd"});
    EXPECT_EQ(inComment.exitCode, 1);
    EXPECT_NE(inComment.err.find("c.frag:3:1: error: line 3 holds no statement (it is blank, a comment or a "
                                 "directive): watch a line with one\n   to a second line { and a brace */\n^\n"),
              std::string::npos)
        << inComment.err;
}

// A fragment stage's own `out` becomes a global wherever it is declared,
// after a function too (issue 40: a function's closing brace taken for its
// body's made everything after the first function look nested, and the
// watch's outputs then clashed with the shader's at link).
TEST(CliWatch, AnOutputDeclaredAfterAFunctionIsWatchedToo) {
    TempDir dir;
    writeOneProgram(dir,
                    "#version 330 compatibility\nout vec2 vST;\n"
                    "void main() { vST = gl_MultiTexCoord0.st; gl_Position = ftransform(); }\n",
                    "#version 330 core\nin vec2 vST;\nfloat halved(float x) { return x / 2.; }\n"
                    "layout(location = 0) out vec4 color;\nuniform float uAdd;\nvoid main() {\n"
                    "    float h = halved(uAdd);\n    color = vec4(h, vST, 1.);\n}\n");
    auto r = runGlimmer({"render", dir.file("s.glib"), "--backend", "osmesa", "--size", "16x16", "--set", "uAdd=3",
                         "--watch", "c.frag:7:h", "-o", dir.file("k.png")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "watch c.frag:7 h, pass 1 (Program C): float over 16x16: range 1.5 .. 1.5 (its own)\n") << r.err;
}

}  // namespace
}  // namespace glimmer_cli
