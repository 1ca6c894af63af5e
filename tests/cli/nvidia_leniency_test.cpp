// What NVIDIA accepted (issue 19): a local const initialised from a
// non-constant expression compiles (GLSL 4.20 allows it; Mesa does once
// ARB_shading_language_420pack is on), with a warning that says so; a global
// one stays an error, with a note that names the cause and the fix. A
// '#version 400' shader (the core profile) using compatibility built-ins
// compiles as 'compatibility', with a warning; a real error in one stays.
#include <gtest/gtest.h>

#include <fstream>

#include "cli/run_glimmer.h"
#include "image/image.h"

namespace glimmer_cli {
namespace {

TEST(CliNvidiaLeniency, ALocalConstFromAUniformIsAcceptedAndSaidSo) {
    TempDir dir;
    const std::string shader = cliData("const_local.frag");
    auto r = runGlimmer({"render", cliData("const_local.glib"), "-o", dir.file("o.png"), "--size", "16x16",
                         "--backend", "osmesa"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.substr(0, r.err.find("wrote ")),
              shader + ":7:19: warning: a local const set from a non-constant expression (`k2'): accepted, as GLSL "
                       "4.20 allows and NVIDIA does in any version; GL_ARB_shading_language_420pack turned on for "
                       "this shader\n"
                       "    const float k2 = uK * 2.;\n"
                       "                  ^\n");
    // k2 = 2 uK = 1: full red.
    glimmer::Image img;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("o.png"), img, why)) << why;
    EXPECT_EQ(img.u8[(8 * 16 + 8) * 4 + 0], 255);
    EXPECT_EQ(img.u8[(8 * 16 + 8) * 4 + 1], 128);
}

TEST(CliNvidiaLeniency, AGlobalConstFromAUniformStaysAnErrorWithItsFix) {
    const std::string shader = cliData("const_global.frag");
    auto r = runGlimmer({"check", cliData("const_global.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.err, shader + ":5:18: error: initializer of const variable `k2' must be a constant expression [driver]\n"
                              "const float k2 = uK * 2.;\n"
                              "                 ^\n" +
                         shader + ":5:18: note: `k2' is a const outside any function: its initialiser must be a "
                                  "constant expression in every GLSL version (4.20 relaxed it only inside functions); "
                                  "remove 'const' and it is set when the shader starts\n"
                                  "const float k2 = uK * 2.;\n"
                                  "                 ^\n"
                                  "1 error, 0 warnings\n");
}

TEST(CliNvidiaLeniency, ACoreVersionWithCompatibilityBuiltinsCompilesAsCompatibilityAndSaysSo) {
    TempDir dir;
    const std::string vert = cliData("core_version.vert");
    auto r = runGlimmer({"render", cliData("core_version.glib"), "-o", dir.file("core.png"), "--size", "16x16",
                         "--backend", "osmesa"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.substr(0, r.err.find("wrote ")),
              vert + ":1:1: warning: '#version 400' with no profile is the core profile, which has no "
                     "gl_MultiTexCoord0: compiled as '#version 400 compatibility', as NVIDIA's driver does; write "
                     "'compatibility' after 400 to run everywhere\n"
                     "#version 400\n"
                     "^\n");
    // The picture is the one of the same shaders saying 'compatibility'.
    auto same = runGlimmer({"render", cliData("core_version_compat.glib"), "-o", dir.file("compat.png"), "--size",
                            "16x16", "--backend", "osmesa"});
    ASSERT_EQ(same.exitCode, 0) << same.err;
    EXPECT_EQ(same.err.find("warning"), std::string::npos) << same.err;
    glimmer::Image core, compat;
    std::string why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("core.png"), core, why)) << why;
    ASSERT_TRUE(glimmer::loadImage(dir.file("compat.png"), compat, why)) << why;
    EXPECT_EQ(core.u8, compat.u8);
    EXPECT_EQ(core.u8[(8 * 16 + 8) * 4 + 0], 128);  // uK = .5 in red
}

TEST(CliNvidiaLeniency, ACoreVersionShaderWithARealErrorKeepsTheDriversMessage) {
    TempDir dir;
    std::string text = "#version 400\nout vec2 vST;\nvoid main() { vST = noSuchThing; gl_Position = gl_Vertex; }\n";
    std::ofstream(dir.file("bad.vert")) << text;
    std::ofstream(dir.file("red.frag")) << "#version 400 compatibility\nin vec2 vST;\nvoid main() { gl_FragColor = "
                                           "vec4(1., vST, 1.); }\n";
    std::ofstream(dir.file("s.glib")) << "Ortho -1 1 -1 1\nVertex bad.vert\nFragment red.frag\nProgram P\nQuadXY 0 1\n";
    auto r = runGlimmer({"check", dir.file("s.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("`noSuchThing' undeclared"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("compiled as '#version 400 compatibility'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace glimmer_cli
