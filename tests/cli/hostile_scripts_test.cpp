// Hostile scripts made here: each ends with exit 1 or 2 and a compiler-style
// message, never an abort, a hang or a flood.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

const std::string kData = std::string(GLIMMER_SOURCE_DIR) + "/tests/data/cli/";

RunResult check(const std::string& script) { return checkOnOsmesa(script); }

TEST(CliHostile, AFolderAsTheScriptIsAUsageError) {
    TempDir dir;
    auto r = check(dir.path().string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err, dir.path().string() + ": error: cannot read the script: it is a folder, not a file\n"
                     "1 error, 0 warnings\n");
}

TEST(CliHostile, ProcFilesAreNotReadAsShaders) {
    TempDir dir;
    auto s = writeFile(dir, "env.glib", "Vertex /proc/self/environ\nFragment /proc/self/environ\nProgram P\nQuadXY 0 1\n");
    auto r = check(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(s + ":1:8: error: cannot read shader '/proc/self/environ': it is not a regular file\n"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("PATH="), std::string::npos) << r.err;
}

TEST(CliHostile, ProcMemAsATextureIsAnErrorNotAnAbort) {
    TempDir dir;
    auto s = writeFile(dir, "mem.glib", "Texture2D 5 /proc/self/mem\nQuadXY 0 1\n");
    auto r = check(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, s + ":1:1: error: cannot load '/proc/self/mem': /proc/self/mem is not a regular file\n"
                         "Texture2D 5 /proc/self/mem\n^\n1 error, 0 warnings\n");
}

// A FIFO is not a file the script can name: it is not found, and nothing
// waits for a writer.
TEST(CliHostile, AFifoAsATextureIsRefusedWithoutWaiting) {
    TempDir dir;
    const std::string fifo = dir.file("pipe.png");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto s = writeFile(dir, "fifo.glib", "Texture2D 5 pipe.png\nQuadXY 0 1\n");
    auto r = runGlimmer({"check", s, "--backend", "osmesa"}, 20);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(s + ":1:13: error: cannot find texture 'pipe.png'"), std::string::npos) << r.err;
}

TEST(CliHostile, HugeShapeCountsAreBoundedInThePlan) {
    TempDir dir;
    auto s = writeFile(dir, "big.glib", "Sphere 1 100000 100000\nTorus 1 .5 3000000000 3\nQuadXY 0 1 1e9 1\n");
    auto r = check(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, s + ":1:10: error: Sphere's counts must be whole numbers from 2 to 1000; not '100000'\n"
                         "Sphere 1 100000 100000\n         ^\n" +
                         s + ":2:12: error: Torus's counts must be whole numbers from 3 to 1000; not '3000000000'\n"
                         "Torus 1 .5 3000000000 3\n           ^\n" +
                         s + ":3:12: error: QuadXY's counts must be whole numbers from 1 to 1000; not '1e9'\n"
                         "QuadXY 0 1 1e9 1\n           ^\n"
                         "3 errors, 0 warnings\n");
}

TEST(CliHostile, HugeNumbersAreErrorsNotOverflows) {
    TempDir dir;
    auto s = writeFile(dir, "huge.glib", "WindowSize 1e20 1\nTranslate 1e300 0 0\nWindowSize 1e47 1\nQuadXY 0 1\n");
    auto r = check(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, s + ":1:1: error: WindowSize must be between 1 and 16384 pixels each way\n"
                         "WindowSize 1e20 1\n^\n" +
                         s + ":2:11: error: Translate: '1e300' is out of range (at most 1e30 either way)\n"
                         "Translate 1e300 0 0\n          ^\n" +
                         s + ":3:12: error: WindowSize: '1e47' is out of range (at most 1e30 either way)\n"
                         "WindowSize 1e47 1\n           ^\n"
                         "3 errors, 0 warnings\n");
}

TEST(CliHostile, AHugeProgramConstantIsNotAnIntOverflow) {
    TempDir dir;
    auto s = writeFile(dir, "const.glib", "Vertex " + kData + "plain.vert\nFragment " + kData + "solid.frag" +
                                              "\nProgram P uLevel 1e24\nQuadXY 0 1\n");
    auto r = runGlimmer({"-q", "render", s, "-o", dir.file("o.png"), "--size", "8x8", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");  // -q: errors only, and there are none
}

TEST(CliHostile, OnlyAHundredDiagnosticsArePrinted) {
    TempDir dir;
    std::string text;
    for (int i = 0; i < 150; ++i) text += "Frobnicate\n";
    auto s = writeFile(dir, "many.glib", text);
    // -v: every diagnostic, unfolded; still at most 100 of them.
    auto r = runGlimmer({"-v", "check", s, "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(countOf(r.err, ": warning: unknown command 'Frobnicate'"), 100);
    // 150 unknown lines and "draws nothing": 51 not shown.
    EXPECT_NE(r.err.find("\n... 51 more diagnostics not shown\n"), std::string::npos) << r.err.substr(r.err.size() - 200);
}

TEST(CliHostile, AMegabyteLineOfBadNumbersDoesNotFlood) {
    TempDir dir;
    std::string line = "Translate";
    while (line.size() < 1000000) line += " 1.2.3.4";
    auto s = writeFile(dir, "flood.glib", line + "\n");
    auto r = runGlimmer({"-v", "check", s, "--backend", "osmesa"}, 60);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_LT(r.err.size(), 100000u);
    EXPECT_NE(r.err.find(" more diagnostics not shown\n"), std::string::npos);
}

TEST(CliHostile, TerminalEscapesInTheScriptAreShownEscaped) {
    TempDir dir;
    auto s = writeFile(dir, "esc.glib", "Frob\x1b]0;owned\x07 1\n");
    auto r = check(s);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, s + ":1:1: warning: unknown command 'Frob\\x1b'; line ignored\n"
                         "Frob\\x1b]0;owned\\x07 1\n^\n" +
                         s + ": warning: the script draws nothing; the picture is only its background colour\n");
}

}  // namespace
}  // namespace glimmer_cli

namespace glimmer_cli {
namespace {

// A script folder with a shader and an image, and secrets beside it.
struct Sandbox {
    TempDir dir;
    std::string scripts, secret;
    Sandbox() {
        fs::create_directories(dir.path() / "class" / "student");
        scripts = (dir.path() / "class" / "student").string();
        secret = writeFile(dir, "secret.frag", "#version 330 compatibility\nvoid main() { gl_FragColor = vec4(1.); }\n");
        fs::copy_file(kData + "plain.vert", scripts + "/plain.vert");
        fs::copy_file(kData + "solid.frag", scripts + "/solid.frag");
        fs::create_symlink(secret, scripts + "/link.frag");
    }
    std::string script(const std::string& text) const {
        std::string p = scripts + "/s.glib";
        std::ofstream(p) << text;
        return p;
    }
};

RunResult checkSandboxed(const std::string& script, std::vector<std::string> extra = {}) {
    extra.insert(extra.begin(), "--sandbox");
    return checkOnOsmesa(script, extra);
}

const std::string kOutsideTail = "; --sandbox reads only files in the script's folder and -I folders\n";

TEST(CliSandbox, FilesInTheScriptsFolderAreRead) {
    Sandbox sb;
    auto r = checkSandboxed(sb.script("Vertex plain.vert\nFragment solid.frag\nProgram P uLevel <0. .5 1.>\nQuadXY 0 1\n"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(CliSandbox, AbsolutePathsDotDotAndSymlinksOutAreRefused) {
    Sandbox sb;
    auto s = sb.script("Vertex /etc/passwd\nFragment ../../secret.frag\nFragment link.frag\nTexture2D 5 /proc/self/environ\n");
    auto r = checkSandboxed(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, s + ":1:8: error: shader '/etc/passwd' is outside the sandbox (an absolute path)" + kOutsideTail +
                         "Vertex /etc/passwd\n       ^\n" +
                         s + ":2:10: error: shader '../../secret.frag' is outside the sandbox (it leads outside the script's folder)" +
                         kOutsideTail + "Fragment ../../secret.frag\n         ^\n" +
                         s + ":3:10: error: shader 'link.frag' is outside the sandbox (it leads outside the script's folder)" +
                         kOutsideTail + "Fragment link.frag\n         ^\n" +
                         s + ":4:13: error: texture '/proc/self/environ' is outside the sandbox (an absolute path)" +
                         kOutsideTail + "Texture2D 5 /proc/self/environ\n            ^\n"
                         "4 errors, 0 warnings\n");
}

// The message never names a link's target, and a name that leads out is
// refused in the same words whether a file is there or not: a student
// learns nothing of the disk outside the folder (issue 30).
TEST(CliSandbox, LeavingTheFolderTellsNothingOfWhatIsOutside) {
    Sandbox sb;
    fs::create_symlink(sb.dir.path() / "no-such.frag", sb.scripts + "/dangling.frag");
    auto s = sb.script("Fragment ../../secret.frag\nFragment ../../no-such.frag\nFragment link.frag\nFragment dangling.frag\n");
    auto r = checkSandboxed(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(countOf(r.err, "is outside the sandbox (it leads outside the script's folder)"), 4) << r.err;
    EXPECT_EQ(r.err.find(fs::canonical(sb.secret).string()), std::string::npos) << "a target was printed: " << r.err;
    EXPECT_EQ(r.err.find("cannot find"), std::string::npos) << r.err;
}

// A hard link is the outside file under a name inside: refused, since no
// check can tell where its other name is.
TEST(CliSandbox, AHardLinkIsRefused) {
    Sandbox sb;
    ASSERT_EQ(::link(sb.secret.c_str(), (sb.scripts + "/hard.frag").c_str()), 0);
    auto s = sb.script("Vertex plain.vert\nFragment hard.frag\nProgram P\nQuadXY 0 1\n");
    auto r = checkSandboxed(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(s + ":2:10: error: shader 'hard.frag' is outside the sandbox (a file with 2 hard links "
                             "(another name may be outside the script's folder))" + kOutsideTail),
              std::string::npos)
        << r.err;
}

TEST(CliSandbox, AnIncludeFolderWidensTheSandbox) {
    Sandbox sb;
    auto s = sb.script("Vertex plain.vert\nFragment secret.frag\nProgram P\nQuadXY 0 1\n");
    auto r = checkSandboxed(s, {"-I", sb.dir.path().string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    // and without -I it is not found (the project folders are not searched)
    r = checkSandboxed(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("error: cannot find shader 'secret.frag' (looked in " + sb.scripts + ")"), std::string::npos)
        << r.err;
}

TEST(CliSandbox, AFolderNamedAsATextureIsRefused) {
    Sandbox sb;
    fs::create_directories(sb.scripts + "/pics");
    auto s = sb.script("Texture2D 5 pics\n");
    auto r = checkSandboxed(s);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(s + ":1:13: error: texture 'pics' is outside the sandbox (not a regular file)"),
              std::string::npos)
        << r.err;
}

TEST(CliLimits, TargetsPastTheMemoryBudgetAreAnErrorOnTheirLine) {
    TempDir dir;
    auto s = writeFile(dir, "mem.glib", "Texture2D 6 16384 16384 RGBA32F\nRenderToTexture 6\nQuadXY 0 1\n");
    auto r = runGlimmer({"check", s, "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, s + ":1:1: error: the script's textures, targets, meshes and parsed lines need 4099 MiB by this line, more than the memory "
                         "budget of 2048 MiB (--max-memory)\n"
                         "Texture2D 6 16384 16384 RGBA32F\n^\n1 error, 0 warnings\n");
    r = runGlimmer({"check", s, "--backend", "osmesa", "--max-memory", "1"});
    EXPECT_NE(r.err.find("need 4099 MiB by this line, more than the memory budget of 1 MiB"), std::string::npos) << r.err;
}

TEST(CliLimits, ImageFilesCountAgainstTheMemoryBudget) {
    // grid.bmp decodes to 512 x 512 RGBA8: 1 MiB, which a 1 MiB budget
    // cannot hold beside a 16 x 16 screen; 2 MiB can.
    TempDir dir;
    std::string grid = std::string(GLIMMER_SOURCE_DIR) + "/textures/grid.bmp";
    auto s = writeFile(dir, "img.glib", "WindowSize 16 16\nTexture2D 5 " + grid + "\nQuadXY 0 1\n");
    auto r = runGlimmer({"check", s, "--backend", "osmesa", "--max-memory", "1"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, s + ":2:1: error: the script's textures, targets, meshes and parsed lines need 2 MiB by this line, more than the memory "
                         "budget of 1 MiB (--max-memory)\n"
                         "Texture2D 5 " + grid + "\n^\n1 error, 0 warnings\n");
    r = runGlimmer({"-q", "check", s, "--backend", "osmesa", "--max-memory", "2"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
}  // namespace glimmer_cli
