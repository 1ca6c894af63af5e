// `glimmer check`-style runs (load, plan, prepare everything) and the
// diagnostics they give: every GLIB command known, NVIDIA-only geometry
// shaders translated with one warning, uniform forms that do not fit their type,
// and the built-in noise made only when a program declares it.
#include <fstream>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>

#include "glman_harness.h"

using namespace glimmer;
using namespace glimmer::glmantest;

namespace {

TEST(GlmanCheck, EveryCommandOfGlibNotesIsSupported) {
    auto r = runPipeline(script("all_commands"), true, true);
    ASSERT_TRUE(r->renderer) << r->printed();
    for (const auto& d : r->diags.all())
        EXPECT_EQ(d.message.find("not supported"), std::string::npos) << d.loc.line << ": " << d.message;
    EXPECT_EQ(r->diags.errorCount(), 0) << r->printed();
    EXPECT_EQ(r->diags.warningCount(), 0) << r->printed();
    EXPECT_TRUE(r->prepared) << r->printed();
    // Every command word of the language appears in the script.
    std::set<CommandKind> used;
    for (const auto& c : r->loaded.script.commands) used.insert(c.kind);
    for (int k = int(CommandKind::WindowSize); k <= int(CommandKind::QuadBox); ++k)
        EXPECT_TRUE(used.count(CommandKind(k))) << "all_commands.glib lacks " << commandName(CommandKind(k));
}

TEST(GlmanCheck, GlPositionInIsTranslatedForMesa) {
    // Written for NVIDIA: Mesa alone says "`gl_PositionIn' undeclared"; the
    // translation (shader/gs4_translate.h) makes it standard GLSL.
    auto r = runPipeline(script("positionin"), true, false);
    ASSERT_TRUE(r->renderer) << r->printed();
    EXPECT_TRUE(r->prepared) << r->printed();
    ASSERT_EQ(r->diags.all().size(), 1u) << r->printed();
    const Diagnostic& d = r->diags.all()[0];
    EXPECT_EQ(d.severity, Severity::Warning);
    EXPECT_EQ(std::filesystem::path(d.file).filename(), "positionin.geom");
    EXPECT_EQ(d.loc.line, 8);
    EXPECT_EQ(d.message, "GL_EXT_geometry_shader4 shader (NVIDIA) translated to standard GLSL: "
                         "gl_PositionIn[i] -> gl_in[i].gl_Position");
}

TEST(GlmanCheck, UniformFormsThatDoNotFitAreWarnedAndConverted) {
    auto r = runPipeline(script("uniform_forms"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{
                  "uniform 'uFlag' is given a checkbox but its shader declares it float; 1 is used",
                  "uniform 'uTint' is given a range but its shader declares it vec3; the value is copied to all 3 "
                  "components",
                  "uniform 'uGrey' is given a colour but its shader declares it float; its luminance (0.2126 r + "
                  "0.7152 g + 0.0722 b) is used"}));
    std::vector<int> lines;
    for (const auto& d : r->diags.all()) lines.push_back(d.loc.line);
    EXPECT_EQ(lines, (std::vector<int>{8, 8, 8}));
    // Left third: uFlag = 1; middle: vec3(.5); right: luminance of red.
    EXPECT_EQ(int(pixel(r->screen, 10, 48)[0]), 255);
    EXPECT_NEAR(int(pixel(r->screen, 48, 48)[1]), 128, 1);
    EXPECT_NEAR(int(pixel(r->screen, 86, 48)[2]), 54, 1);  // 0.2126 * 255
}

// A checkbox that is off, or written <0>/<1>, on a float or a vector: the
// warning names the 0 or 1 used, and the picture shows it.
TEST(GlmanCheck, ACheckboxOnANumberIsZeroWhenOffAndSaysSo) {
    auto r = runPipeline(script("uniform_checkbox_off"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{
                  "uniform 'uFlag' is given a checkbox but its shader declares it float; 0 is used",
                  "uniform 'uTint' is given a checkbox but its shader declares it vec3; every component is 0",
                  "uniform 'uGrey' is given a checkbox but its shader declares it float; 1 is used"}));
    EXPECT_EQ(int(pixel(r->screen, 10, 48)[0]), 0);    // uFlag
    EXPECT_EQ(int(pixel(r->screen, 48, 48)[1]), 0);    // uTint
    EXPECT_EQ(int(pixel(r->screen, 86, 48)[2]), 255);  // uGrey
}

// Issue 26: the conversions the first script does not reach, each read
// back from its sixth of the picture (8-bit values of .2 = 51, .4 = 102, ...).
TEST(GlmanCheck, MoreUniformFormsAreConvertedAsTheWarningsSay) {
    auto r = runPipeline(script("uniform_forms_more"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{
                  "uniform 'uOn' is given a checkbox but its shader declares it vec3; every component is 1",
                  "uniform 'uM' is given a range but its shader declares it mat2; the value times the identity is used",
                  "uniform 'uPart' is given an array but its shader declares it vec3; the missing components are 0",
                  "uniform 'uExtra' is given an array but its shader declares it vec2; the extra values are dropped"}));
    auto rgb = [&](int sixth) {
        const std::uint8_t* p = pixel(r->screen, sixth * 16 + 8, 48);
        return std::vector<int>{p[0], p[1], p[2]};
    };
    EXPECT_EQ(rgb(0), (std::vector<int>{255, 255, 255}));  // uOn: every component
    EXPECT_EQ(rgb(1), (std::vector<int>{153, 0, 0}));      // uN: 2.7 rounds to 3, 3 / 5 = .6
    EXPECT_EQ(rgb(2), (std::vector<int>{128, 0, 128}));    // uM: the diagonal .5, the rest 0
    EXPECT_EQ(rgb(3), (std::vector<int>{51, 102, 0}));     // uPart: .2 .4, then 0
    EXPECT_EQ(rgb(4), (std::vector<int>{51, 102, 0}));     // uExtra: .2 .4; .6 .8 dropped
    EXPECT_EQ(rgb(5), (std::vector<int>{51, 102, 153}));   // uW[0..2]
}

// A type no GLIB form can set (an unsigned int) is named in its warning and
// left at 0: the picture shows the 0, not the script's numbers.
TEST(GlmanCheck, UniformsOfATypeNoFormSetsAreWarnedAndLeftAtZero) {
    auto r = runPipeline(script("uniform_not_set"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{
                  "uniform 'uCount' is given a range but its shader declares it uint; it is not set",
                  "uniform 'uPair' is given an array but its shader declares it uvec2; it is not set"}));
    const std::uint8_t* left = pixel(r->screen, 24, 48);
    const std::uint8_t* right = pixel(r->screen, 72, 48);
    EXPECT_EQ((std::vector<int>{left[0], left[1], left[2]}), (std::vector<int>{0, 255, 0}));
    EXPECT_EQ((std::vector<int>{right[0], right[1], right[2]}), (std::vector<int>{0, 0, 255}));
}

TEST(GlmanCheck, NoiseIsMadeOnlyForProgramsThatDeclareIt) {
    auto plain = runPipeline(script("quad_texture"), true, true);
    ASSERT_TRUE(plain->prepared) << plain->printed();
    EXPECT_EQ(plain->renderer->noiseTexturesMade(), 0u);
    auto noisy = runPipeline(script("noise"), true, true);
    ASSERT_TRUE(noisy->prepared) << noisy->printed();
    EXPECT_EQ(noisy->renderer->noiseTexturesMade(), 2u);
    // A second prepare of the same renderer reuses them.
    ASSERT_TRUE(loadAndUpload(*noisy->renderer, noisy->loaded, false, noisy->diags));
    EXPECT_EQ(noisy->renderer->noiseTexturesMade(), 2u);
}

// The built-in noise goes on unit 2 only when the script put no 2-D texture
// there: the script's grid3.bmp (its middle cell cyan) is what a Noise2 sent
// to unit 2 reads.
TEST(GlmanCheck, TheScriptsOwnTextureOnUnit2IsWhatNoise2Reads) {
    auto r = runPipeline(script("noise_unit_taken"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    const std::uint8_t* middle = pixel(r->screen, 48, 48);
    EXPECT_LT(middle[0], 60) << int(middle[0]) << " " << int(middle[1]) << " " << int(middle[2]);
    EXPECT_GT(middle[1], 200);
    EXPECT_GT(middle[2], 200);
}

TEST(GlmanCheck, ShapesAProgramCannotDrawAreWarnedNotDrawn) {
    // A tessellation program given a sphere, a patch without one.
    std::string dir = dataDir();
    auto path = std::filesystem::temp_directory_path() / ("glimmer_mismatch_" + std::to_string(::getpid()) + ".glib");
    std::ofstream(path) << "WindowSize 32 32\n"
                           "glBegin gl_patches\nglVertex 0 0 0\nglVertex 1 0 0\nglVertex 0 1 0\nglEnd\n"
                           "Vertex " << dir << "/pass.vert\nGeometry " << dir << "/adj.geom\nFragment " << dir
                        << "/patch.frag\nProgram Adj\nSphere\n";
    auto r = runPipeline(path.string(), true, true);
    std::filesystem::remove(path);
    EXPECT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{
                  "patches (glBegin gl_patches) need a Program with a TessEvaluation shader; not drawn",
                  "the geometry shader of Program Adj takes triangles_adjacency, but this shape is triangles; not "
                  "drawn"}));
}

TEST(GlmanCheck, ASamplerOfTheWrongKindForItsUnitIsWarnedOnItsProgramLine) {
    auto r = runPipeline(script("sampler_kinds"), false, true);
    EXPECT_TRUE(r->prepared) << r->printed();
    std::vector<std::string> lines;
    for (const auto& d : r->diags.all())
        lines.push_back(std::to_string(d.loc.line) + ": " + std::string(severityName(d.severity)) + ": " + d.message);
    EXPECT_EQ(lines, (std::vector<std::string>{
                         // Two draws, one warning.
                         "10: warning: Program Slice: sampler3D uVol reads unit 5, which holds a 2-D texture "
                         "(line 5); it reads black",
                         // Not Right: line 15 puts an image on unit 7's 2-D target, and the
                         // volume stays on its 3-D target (one binding per target, as in OpenGL).
                         "18: warning: Program Flat: sampler2D uTex reads unit 6, which holds a cube map "
                         "(line 7); it reads black"}))
        << r->printed();
}

TEST(GlmanCheck, AWrongKindOfSamplerReadsBlack) {
    std::string dir = dataDir();
    auto path = std::filesystem::temp_directory_path() / ("glimmer_kinds_" + std::to_string(::getpid()) + ".glib");
    std::ofstream(path) << "WindowSize 32 32\nOrtho -1 1 -1 1\nTexture2D 5 " << dir << "/grid3.bmp\nVertex " << dir
                        << "/pass.vert\nFragment " << dir << "/vol.frag\nProgram Slice uVol 5 uR 0.5\nQuadXY 0 2\n";
    auto r = runPipeline(path.string(), false, true);
    std::filesystem::remove(path);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{"Program Slice: sampler3D uVol reads unit 5, which holds a 2-D texture "
                                        "(line 3); it reads black"}));
    for (int y = 0; y < 32; y += 8)
        for (int x = 0; x < 32; x += 8) {
            const std::uint8_t* p = pixel(r->screen, x, y);
            EXPECT_EQ(p[0] + p[1] + p[2], 0) << x << "," << y;
        }
}

// What a unit holds is what the script had bound at the draw's line, in
// every frame: a volume bound after the left quad's line is not there for
// it in the second frame either (as in `render --frames` and the viewer).
TEST(GlmanCheck, ADrawReadsWhatItsUnitHeldAtItsLineInEveryFrame) {
    auto r = runPipeline(script("unit_kind_later"), false, true);
    ASSERT_TRUE(r->prepared) << r->printed();
    EXPECT_EQ(r->messages(Severity::Warning),
              (std::vector<std::string>{"Program Slice: sampler3D uVol reads unit 5, which holds a 2-D texture "
                                        "(line 9); it reads black"}));
    UniformValues values(r->loaded.plan);
    for (int frame = 1; frame <= 2; ++frame) {
        if (frame == 2) {
            r->renderer->render(values, 0.0);
            r->screen = r->renderer->readScreen();
        }
        const std::uint8_t* left = pixel(r->screen, 8, 16);
        const std::uint8_t* right = pixel(r->screen, 24, 16);
        EXPECT_EQ(left[0] + left[1] + left[2], 0) << "frame " << frame;
        EXPECT_GT(right[0] + right[1] + right[2], 0) << "frame " << frame << ": the volume is not there";
    }
}

}  // namespace
