// Messy but honest work is read (issue 29): a byte-order mark an editor put
// before #version or a script's first line, and a file named in another
// letter case than the one on disk (written where names ignore case).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

const std::string kBom = "\xEF\xBB\xBF";

std::string plainVert(const TempDir& dir) {
    fs::copy_file(std::string(GLIMMER_SOURCE_DIR) + "/" + cliData("plain.vert"), dir.file("plain.vert"));
    return dir.file("plain.vert");
}

TEST(CliMessyWork, AByteOrderMarkBeforeVersionIsReadAsBlanksWithANote) {
    TempDir dir;
    plainVert(dir);
    writeFile(dir, "bom.frag", kBom + "#version 120\nvoid main() { gl_FragColor = vec4(1., .5, 0., 1.); }\n");
    auto s = writeFile(dir, "bom.glib", kBom + "Ortho -1 1 -1 1\nVertex plain.vert\nFragment bom.frag\nProgram P\nQuadXY 0 2\n");
    auto r = runGlimmer({"render", s, "--size", "8x8", "--backend", "osmesa", "-o", dir.file("o.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find(s + ":1:1: note: a UTF-8 byte-order mark starts this file (an editor put it there); read as "
                             "nothing\n"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(dir.file("bom.frag") + ":1:1: note: a UTF-8 byte-order mark starts this file (an editor put it "
                                                "there); read as blanks, since GLSL compilers refuse it\n"),
              std::string::npos) << r.err;
    glimmer::Image img = loadPicture(dir.file("o.png"));
    ASSERT_EQ(img.u8.size(), 8u * 8u * 4u);
    EXPECT_EQ(img.u8[(4 * 8 + 4) * 4 + 0], 255);
    EXPECT_EQ(img.u8[(4 * 8 + 4) * 4 + 1], 128);
}

// glman ran on Windows, whose file names ignore case (issue 37): a script
// naming Bright.frag beside bright.frag opens it, with a warning naming
// both spellings; under --sandbox too. A name with no such file is still
// an error.
TEST(CliMessyWork, ANameInAnotherCaseOpensTheFileWithAWarningNamingBoth) {
    TempDir dir;
    plainVert(dir);
    writeFile(dir, "bright.frag", "void main() { gl_FragColor = vec4(1.); }\n");
    auto s = writeFile(dir, "case.glib", "Vertex plain.vert\nFragment Bright.frag\nProgram P\nQuadXY 0 1\n");
    const std::string warning = s + ":2:10: warning: shader 'Bright.frag' is 'bright.frag' on disk: opened it, as Windows "
                                    "and macOS do; write it 'bright.frag' for Linux\n";
    for (bool sandbox : {false, true}) {
        std::vector<std::string> args = {"render", s, "--backend", "osmesa", "--size", "8x8", "-o", dir.file("o.png")};
        if (sandbox) args.push_back("--sandbox");
        auto r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.rfind(warning, 0), 0u) << r.err;
        glimmer::Image img = loadPicture(dir.file("o.png"));
        ASSERT_EQ(img.u8.size(), 8u * 8u * 4u);
        EXPECT_EQ(img.u8[(4 * 8 + 4) * 4 + 0], 255);  // bright.frag's white
    }
    auto missing = writeFile(dir, "none.glib", "Vertex plain.vert\nFragment Dark.frag\nProgram P\nQuadXY 0 1\n");
    auto r = runGlimmer({"check", missing, "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("error: cannot find shader 'Dark.frag'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace glimmer_cli
