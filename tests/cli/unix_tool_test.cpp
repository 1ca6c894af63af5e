// The command line as a Unix tool: --version, help, defaults in --help, the
// man page, -o -, render -, -q/-v and folded warnings, --set colours and
// vectors, progress with '\r' only on a terminal, one 'wrote' line, and the
// same message and exit code for the same mistake in every command.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"
#include "image/image.h"

namespace glimmer_cli {
namespace {

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

const std::string kFolded =
    "scripts/bloom.glib: warning: 5 uniforms on lines of their own were taken as part of their Program (glman needs "
    "a '\\'); -v to list them\n";

TEST(CliUnix, VersionPrintsNameAndVersion) {
    auto r = runGlimmer({"--version"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::regex_match(r.out, std::regex("glimmer [0-9]+\\.[0-9]+\\.[0-9]+\n"))) << r.out;
}

TEST(CliUnix, HelpCommandIsTheSameAsHelpFlag) {
    auto a = runGlimmer({"help"}), b = runGlimmer({"--help"});
    EXPECT_EQ(a.exitCode, 0);
    EXPECT_EQ(a.out, b.out);
    for (std::string cmd : {"render", "check", "view", "sheet", "tradeoff"}) {
        auto h = runGlimmer({"help", cmd}), f = runGlimmer({cmd, "--help"});
        EXPECT_EQ(h.exitCode, 0) << cmd;
        EXPECT_EQ(h.out, f.out) << cmd;
        EXPECT_NE(h.out.find("Usage: glimmer " + cmd), std::string::npos) << h.out;
    }
    auto bad = runGlimmer({"help", "rendr"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(bad.err, "glimmer: error: help: unknown command 'rendr'; the commands are 'render', 'check', 'view', "
                       "'sheet', 'tradeoff', 'batch', 'batch-merge', 'serve'\n");
}

TEST(CliUnix, HelpStatesTheShortcutAndEveryDefault) {
    auto top = runGlimmer({"--help"});
    EXPECT_NE(top.out.find("`glimmer SCRIPT.glib` is `glimmer view SCRIPT.glib`"), std::string::npos) << top.out;
    auto render = runGlimmer({"help", "render"});
    EXPECT_NE(render.out.find("-o,--output TEXT=out.png"), std::string::npos) << render.out;
    EXPECT_NE(render.out.find("--backend TEXT:{auto,osmesa,egl,egl-device,egl-surfaceless,egl-gles}=auto"), std::string::npos);
    EXPECT_NE(render.out.find("(default: WindowSize, else 600x600)"), std::string::npos);
    EXPECT_NE(render.out.find("--fps FLOAT=24"), std::string::npos);
    EXPECT_NE(render.out.find("--frames INT=1"), std::string::npos);
    EXPECT_EQ(render.out.find("=[]"), std::string::npos) << render.out;
    auto sheet = runGlimmer({"help", "sheet"});
    EXPECT_NE(sheet.out.find("-o,--output TEXT=sheet.png"), std::string::npos) << sheet.out;
    EXPECT_NE(sheet.out.find("(default 256x256)"), std::string::npos);
    auto tradeoff = runGlimmer({"help", "tradeoff"});
    EXPECT_NE(tradeoff.out.find("--repeat INT:INT in [1 - 100000]=5"), std::string::npos) << tradeoff.out;
    EXPECT_NE(tradeoff.out.find("-o,--output TEXT=tradeoff"), std::string::npos);
}

TEST(CliUnix, ManPageComesFromTheSameOptions) {
    auto r = runGlimmer({"--man"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out.rfind(".TH GLIMMER 1", 0), 0u) << r.out;
    for (const char* s : {".SS render", ".SS sheet", ".SS tradeoff", ".B \\-o, \\-\\-output \\fITEXT\\fR",
                          "(default: out.png)", "(default: sheet.png)", ".B \\-\\-frames", ".B \\-q, \\-\\-quiet"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s;
    // The man page built beside the program is this text.
    EXPECT_EQ(slurp(std::string(GLIMMER_BIN_DIR) + "/glimmer.1"), r.out);
}

TEST(CliUnix, OutputDashWritesThePngToStdout) {
    TempDir dir;
    std::vector<std::string> args{"render", "scripts/bloom.glib", "--size", "24x16", "--set", "uAdd=2", "--backend",
                                  "osmesa"};
    auto file = args, pipe = args;
    file.insert(file.end(), {"-o", dir.file("x.png")});
    pipe.insert(pipe.end(), {"-o", "-"});
    auto a = runGlimmer(file), b = runGlimmer(pipe);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(b.out, slurp(dir.file("x.png")));
    EXPECT_EQ(countOf(b.err, "wrote a 24x16 PNG to standard output\n"), 1) << b.err;
}

TEST(CliUnix, PngLevelChangesTheFileNotThePixels) {
    TempDir dir;
    std::vector<std::string> args{"render", "scripts/bloom.glib", "--size", "96x64", "--set", "uAdd=2", "--backend",
                                  "osmesa"};
    std::vector<glimmer::Image> images;
    std::vector<std::size_t> sizes;
    for (std::string level : {"", "0", "9"}) {
        auto a = args;
        const std::string file = dir.file("l" + level + ".png");
        a.insert(a.end(), {"-o", file});
        if (!level.empty()) a.insert(a.end(), {"--png-level", level});
        auto r = runGlimmer(a);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        glimmer::Image img;
        std::string why;
        ASSERT_TRUE(glimmer::loadImage(file, img, why)) << why;
        images.push_back(img);
        sizes.push_back(slurp(file).size());
    }
    EXPECT_TRUE(images[0].u8 == images[1].u8);
    EXPECT_TRUE(images[0].u8 == images[2].u8);
    EXPECT_GT(sizes[1], 96u * 64u * 4u);  // level 0 stores
    EXPECT_LT(sizes[2], sizes[0]);
    // -o - takes the level too: the same bytes as the file.
    auto pipe = args;
    pipe.insert(pipe.end(), {"-o", "-", "--png-level", "9"});
    auto r = runGlimmer(pipe);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, slurp(dir.file("l9.png")));
}

TEST(CliUnix, ScriptFromStdinResolvesAgainstTheCurrentFolder) {
    TempDir dir;
    auto r = runGlimmerWithInput({"render", "-", "--size", "8x8", "--set", "uLevel=1", "--backend", "osmesa", "-o",
                                  dir.file("x.png")},
                                 cliData("stdin.glib"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    glimmer::Image img;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("x.png"), img, why)) << why;
    EXPECT_EQ(img.u8[0], 255);
    EXPECT_EQ(img.u8[1], 0);
    // A mistake in it is reported against <stdin>.
    std::ofstream(dir.file("bad.glib")) << "##OpenGL GLIB\nVertex nowhere.vert\n";
    auto bad = runGlimmerWithInput({"render", "-", "--backend", "osmesa", "-o", dir.file("y.png")}, dir.file("bad.glib"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("<stdin>:2:8: error: cannot find shader 'nowhere.vert'"), std::string::npos) << bad.err;
}

TEST(CliUnix, RepeatedWarningsAreFoldedUnlessVerbose) {
    TempDir dir;
    std::vector<std::string> args{"render", "scripts/bloom.glib", "--size", "16x16", "--backend", "osmesa", "-o",
                                  dir.file("x.png")};
    auto r = runGlimmer(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, kFolded), 1) << r.err;
    EXPECT_EQ(countOf(r.err, "warning: "), 2) << r.err;  // the fold and the degenerate Ortho
    EXPECT_EQ(countOf(r.err, "is on a line of its own"), 0) << r.err;

    auto v = args;
    v.push_back("-v");
    auto rv = runGlimmer(v);
    EXPECT_EQ(countOf(rv.err, "is on a line of its own"), 5) << rv.err;
    EXPECT_EQ(countOf(rv.err, "-v to list them"), 0) << rv.err;

    auto q = args;
    q.insert(q.begin(), "-q");
    auto rq = runGlimmer(q);
    EXPECT_EQ(rq.exitCode, 0);
    EXPECT_EQ(rq.err, "");
    EXPECT_EQ(runGlimmer({"render", "scripts/bloom.glib", "-q", "-v"}).exitCode, 2);
}

TEST(CliUnix, QuietStillPrintsErrors) {
    TempDir dir;
    auto r = runGlimmer({"-q", "render", "scripts/bloom.glib", "--set", "uAdd=9", "--backend", "osmesa", "-o",
                         dir.file("x.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err,
              "scripts/bloom.glib:29:5: error: --set uAdd=9 is outside the range <0 4> of uniform 'uAdd' in Program "
              "Bloom\n    uAdd <0. 0. 4.00>\n    ^\n1 error\n");
}

glimmer::Image renderColour(const std::vector<std::string>& sets, int& exitCode, std::string& err) {
    TempDir dir;
    std::vector<std::string> args{"render", cliData("colour.glib"), "--size", "4x4", "--backend", "osmesa", "-o",
                                  dir.file("c.png")};
    for (const auto& s : sets) args.insert(args.end(), {"--set", s});
    auto r = runGlimmer(args);
    exitCode = r.exitCode;
    err = r.err;
    glimmer::Image img;
    std::string why;
    if (r.exitCode == 0) glimmer::loadImage(dir.file("c.png"), img, why);
    return img;
}

TEST(CliUnix, SetTakesColoursAndVectors) {
    int code = 0;
    std::string err;
    glimmer::Image plain = renderColour({}, code, err);
    ASSERT_EQ(code, 0) << err;
    EXPECT_EQ(plain.u8[0], 0);
    EXPECT_EQ(plain.u8[1], 255);
    glimmer::Image set = renderColour({"uColor=1,0,0.2", "uOffset=0,0.2,0"}, code, err);
    ASSERT_EQ(code, 0) << err;
    EXPECT_EQ(set.u8[0], 255);
    EXPECT_EQ(set.u8[1], 51);
    EXPECT_EQ(set.u8[2], 51);
    renderColour({"uColor=1,0"}, code, err);
    EXPECT_EQ(code, 2);
    EXPECT_NE(err.find("error: --set uColor=1,0: uniform 'uColor' of Program Solid is a colour and takes R,G,B or "
                       "R,G,B,A"),
              std::string::npos)
        << err;
}

TEST(CliUnix, ProgressUsesCarriageReturnsOnlyOnATerminal) {
    TempDir dir;
    std::vector<std::string> args{"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,2,4", "--size", "16x16",
                                  "--backend", "osmesa", "-o", dir.file("s.png")};
    auto logged = runGlimmer(args);
    ASSERT_EQ(logged.exitCode, 0) << logged.err;
    EXPECT_EQ(countOf(logged.err, "\r"), 0);
    EXPECT_EQ(countOf(logged.err, "sheet: 1/3 rendered\nsheet: 2/3 rendered\nsheet: 3/3 rendered\n"), 1) << logged.err;
    ::setenv("GLIMMER_TTY", "1", 1);
    auto tty = runGlimmer(args);
    ::unsetenv("GLIMMER_TTY");
    EXPECT_EQ(countOf(tty.err, "\rsheet: 1/3 rendered\rsheet: 2/3 rendered\rsheet: 3/3 rendered\n"), 1) << tty.err;
}

TEST(CliUnix, EveryCommandSaysWhatItWroteOnOneLine) {
    TempDir dir;
    auto r = runGlimmer({"render", "scripts/bloom.glib", "--size", "16x8", "--backend", "osmesa", "-o",
                         dir.file("x.png"), "--dump", "6=" + dir.file("blur.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, "wrote "), 1) << r.err;
    EXPECT_EQ(countOf(r.err, "wrote " + dir.file("x.png") + " (16x8), " + dir.file("blur.png") + " (unit 6)\n"), 1)
        << r.err;
    auto s = runGlimmer({"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,2", "--vary", "uHalfSize=0,1,2", "--size",
                         "16x16", "--backend", "osmesa", "-o", dir.file("s.png")});
    ASSERT_EQ(s.exitCode, 0) << s.err;
    EXPECT_EQ(countOf(s.err, "wrote "), 1) << s.err;
    EXPECT_EQ(countOf(s.err, "wrote " + dir.file("s.png") + " (2 by 3 cells of 16x16, "), 1) << s.err;
}

TEST(CliUnix, AnUnknownNameIsTheSameUsageErrorInEveryCommand) {
    TempDir dir;
    const std::string set = "--set: error: no Program sets a uniform named 'nope'\n";
    const std::string vary = "--vary: error: no Program sets a uniform named 'nope'\n";
    struct Case {
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {{"render", "scripts/bloom.glib", "--set", "nope=1", "-o", dir.file("x.png")}, set},
        {{"check", "scripts/bloom.glib", "--set", "nope=1"}, set},
        {{"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,1", "--set", "nope=1", "-o", dir.file("s.png")}, set},
        {{"sheet", "scripts/bloom.glib", "--vary", "nope=0,1", "-o", dir.file("s.png")}, vary},
        {{"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,1", "--vary", "nope=0,1", "-o", dir.file("s.png")}, vary},
    };
    for (auto& c : cases) {
        c.args.insert(c.args.end(), {"--backend", "osmesa", "--size", "8x8"});
        auto r = runGlimmer(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args[0] << "\n" << r.err;
        EXPECT_EQ(countOf(r.err, c.message), 1) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("s.png")));
}

TEST(CliUnix, AVaryErrorSaysVary) {
    TempDir dir;
    auto r = runGlimmer({"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,9", "--size", "8x8", "--backend", "osmesa",
                         "-o", dir.file("s.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("error: --vary uAdd=9 is outside the range <0 4> of uniform 'uAdd' in Program Bloom"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("--set"), std::string::npos) << r.err;
}

TEST(CliUnix, AScriptThatDrawsNothingSaysSo) {
    TempDir dir;
    const std::string warning = cliData("empty.glib") +
                                ": warning: the script draws nothing; the picture is only its background colour\n";
    auto r = runGlimmer({"render", cliData("empty.glib"), "--size", "4x4", "--backend", "osmesa", "-o",
                         dir.file("x.png")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, warning), 1) << r.err;
    auto c = runGlimmer({"check", cliData("empty.glib"), "--backend", "osmesa"});
    EXPECT_EQ(countOf(c.err, warning), 1) << c.err;
    auto drawn = runGlimmer({"render", cliData("colour.glib"), "--size", "4x4", "--backend", "osmesa", "-o",
                             dir.file("y.png")});
    EXPECT_EQ(countOf(drawn.err, "draws nothing"), 0) << drawn.err;
}

}  // namespace
}  // namespace glimmer_cli
