// What NVIDIA accepted (issue 19): a local const initialised from a
// non-constant expression compiles (GLSL 4.20 allows it; Mesa does once
// ARB_shading_language_420pack is on), with a warning that says so; a global
// one loses its 'const', with a warning (issue 31). A
// '#version 400' shader (the core profile) using compatibility built-ins
// compiles as 'compatibility', with a warning; a real error in one stays.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli/run_glimmer.h"
#include "image/image.h"

namespace glimmer_cli {
namespace {

// Renders `script` at 16x16 on OSMesa into `out`; what it said before "wrote".
std::string renderedSaying(const std::string& script, const std::string& out) {
    auto r = runGlimmer({"render", script, "-o", out, "--size", "16x16", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.err.substr(0, r.err.find("wrote "));
}

// Renders `core` and `compat` at 16x16: `core` says exactly `warning`,
// `compat` warns of nothing, and both draw the same pixels (uK = .5 in red).
void expectTheSamePictureAsCompatibility(const TempDir& dir, const std::string& core, const std::string& compat,
                                         const std::string& warning) {
    EXPECT_EQ(renderedSaying(core, dir.file("core.png")), warning);
    auto same = runGlimmer({"render", compat, "-o", dir.file("compat.png"), "--size", "16x16", "--backend", "osmesa"});
    ASSERT_EQ(same.exitCode, 0) << same.err;
    EXPECT_EQ(same.err.find("warning"), std::string::npos) << same.err;
    glimmer::Image a = loadPicture(dir.file("core.png")), b = loadPicture(dir.file("compat.png"));
    ASSERT_EQ(a.u8.size(), 16u * 16u * 4u);
    EXPECT_EQ(a.u8, b.u8);
    EXPECT_EQ(a.u8[(8 * 16 + 8) * 4 + 0], 128);
}

TEST(CliNvidiaLeniency, ALocalConstFromAUniformIsAcceptedAndSaidSo) {
    TempDir dir;
    const std::string shader = cliData("const_local.frag");
    EXPECT_EQ(renderedSaying(cliData("const_local.glib"), dir.file("o.png")),
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

// Issue 37: the page (check --web, the translation to WebGL 2) takes it as
// the desktop does, with the same words (glslang's column: the '=').
TEST(CliNvidiaLeniency, AGlobalConstFromAUniformIsTakenForTheWebToo) {
    const std::string shader = cliData("const_global.frag");
    auto r = runGlimmer({"check", "--web", cliData("const_global.glib")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, shader + ":5:16: warning: `k2' is a const outside any function set from a non-constant "
                              "expression: 'const' dropped, so it is set when the shader starts, as NVIDIA's driver "
                              "does; remove 'const' to run everywhere\n"
                              "const float k2 = uK * 2.;\n"
                              "               ^\n");
}

// Issue 31: a global const from a uniform is an error in every GLSL version;
// NVIDIA's driver accepted it and the author saw a picture. The 'const' is
// dropped (the value is set when the shader starts), with a warning at its line.
TEST(CliNvidiaLeniency, AGlobalConstFromAUniformLosesItsConstAndSaysSo) {
    TempDir dir;
    const std::string shader = cliData("const_global.frag");
    EXPECT_EQ(renderedSaying(cliData("const_global.glib"), dir.file("o.png")),
              shader + ":5:18: warning: `k2' is a const outside any function set from a non-constant expression: "
                       "'const' dropped, so it is set when the shader starts, as NVIDIA's driver does; remove "
                       "'const' to run everywhere\n"
                       "const float k2 = uK * 2.;\n"
                       "                 ^\n");
    // The picture is the one of the same shader without 'const': k2 = 2 uK = 1, full red.
    std::ifstream in(GLIMMER_SOURCE_DIR "/" + shader);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("const float k2"), 5, "     ");
    std::ofstream(dir.file("plain.frag")) << text;
    std::filesystem::copy_file(GLIMMER_SOURCE_DIR "/" + cliData("st.vert"), dir.file("st.vert"));
    std::ofstream(dir.file("plain.glib")) << "Ortho -1 1 -1 1\nVertex st.vert\nFragment plain.frag\n"
                                             "Program Global uK <0. .5 1.>\nQuadXY 0 1\n";
    auto same = runGlimmer({"-q", "render", dir.file("plain.glib"), "-o", dir.file("plain.png"), "--size", "16x16",
                            "--backend", "osmesa"});
    ASSERT_EQ(same.exitCode, 0) << same.err;
    glimmer::Image lenient = loadPicture(dir.file("o.png")), plain = loadPicture(dir.file("plain.png"));
    ASSERT_FALSE(lenient.u8.empty());
    EXPECT_EQ(lenient.u8, plain.u8);
    EXPECT_EQ(lenient.u8[(8 * 16 + 8) * 4 + 0], 255);
    EXPECT_EQ(lenient.u8[(8 * 16 + 8) * 4 + 1], 128);
}

// Issue 31: a core stage ('#version 400', no profile) between compatibility
// stages: their gl_PerVertex blocks differ and Mesa refuses the link; NVIDIA
// linked it. The core stage is compiled as compatibility, with a warning at
// its #version line, and the picture is the one of all stages saying so.
TEST(CliNvidiaLeniency, ACoreStageAmongCompatibilityOnesLinksAsCompatibility) {
    TempDir dir;
    auto r = runGlimmer({"render", cliData("tess_core.glib"), "-o", dir.file("core.png"), "--size", "32x32",
                         "--backend", "osmesa"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.substr(0, r.err.find("wrote ")),
              cliData("tess_core.tcs") + ":1:1: warning: '#version 400' (no profile: core) has another gl_PerVertex "
                                         "than the compatibility stages: linked as '#version 400 compatibility', as "
                                         "NVIDIA does; add 'compatibility' to run everywhere\n#version 400\n^\n");
    auto same = runGlimmer({"-q", "render", cliData("tess_compat.glib"), "-o", dir.file("compat.png"), "--size",
                            "32x32", "--backend", "osmesa"});
    ASSERT_EQ(same.exitCode, 0) << same.err;
    glimmer::Image core = loadPicture(dir.file("core.png")), compat = loadPicture(dir.file("compat.png"));
    ASSERT_EQ(core.u8.size(), 32u * 32u * 4u);
    EXPECT_EQ(core.u8, compat.u8);
    EXPECT_EQ(core.u8[(16 * 32 + 8) * 4 + 0], 255);  // the triangle's lower left, orange
    EXPECT_EQ(core.u8[(2 * 32 + 30) * 4 + 0], 0);    // its far corner's outside stays black
}

TEST(CliNvidiaLeniency, ACoreVersionWithCompatibilityBuiltinsCompilesAsCompatibilityAndSaysSo) {
    TempDir dir;
    const std::string vert = cliData("core_version.vert");
    // The picture is the one of the same shaders saying 'compatibility'.
    expectTheSamePictureAsCompatibility(dir, cliData("core_version.glib"), cliData("core_version_compat.glib"),
                                        vert + ":1:1: warning: '#version 400' with no profile is the core profile, "
                                               "which has no gl_MultiTexCoord0: compiled as '#version 400 "
                                               "compatibility', as NVIDIA's driver does; write 'compatibility' after "
                                               "400 to run everywhere\n#version 400\n^\n");
}

// Issue 26: the core profile starts at GLSL 1.50, so '#version 150' with no
// profile word is the first version the leniency is for: at 150 itself the
// stage compiles as compatibility, with the warning, and draws what the same
// shaders saying 'compatibility' draw.
TEST(CliNvidiaLeniency, AtVersion150ItselfTheCoreVersionCompilesAsCompatibility) {
    TempDir dir;
    const std::string vert = "#version 150\nout vec2 vST;\nvoid main()\n{\n    vST = gl_MultiTexCoord0.st;\n"
                             "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n}\n";
    const std::string frag = "#version 150 compatibility\nuniform float uK;\nin vec2 vST;\nvoid main()\n{\n"
                             "    gl_FragColor = vec4(uK, vST, 1.);\n}\n";
    std::ofstream(dir.file("core.vert")) << vert;
    std::ofstream(dir.file("compat.vert")) << "#version 150 compatibility" << vert.substr(12);
    std::ofstream(dir.file("k.frag")) << frag;
    for (const char* name : {"core", "compat"})
        std::ofstream(dir.file(std::string(name) + ".glib"))
            << "Ortho -1 1 -1 1\nVertex " << name << ".vert\nFragment k.frag\nProgram P uK <0. .5 1.>\nQuadXY 0 1\n";
    expectTheSamePictureAsCompatibility(dir, dir.file("core.glib"), dir.file("compat.glib"),
                                        dir.file("core.vert") + ":1:1: warning: '#version 150' with no profile is the "
                                                                "core profile, which has no gl_MultiTexCoord0: "
                                                                "compiled as '#version 150 compatibility', as "
                                                                "NVIDIA's driver does; write 'compatibility' after "
                                                                "150 to run everywhere\n#version 150\n^\n");
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
