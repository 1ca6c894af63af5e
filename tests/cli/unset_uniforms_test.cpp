// Uniforms the shaders read but the script never sets (issue 19): each is
// named with its shader's file and line, the value it keeps (0), and where a
// value or slider for it would go.
#include <fstream>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {

// `glimmer check` of a script in `dir` drawing one quad with Program `name`:
// the tests' st.vert and `frag`, written as NAME.frag.
RunResult checkOneProgram(const TempDir& dir, const std::string& name, const std::string& frag) {
    std::ofstream(dir.file(name + ".frag")) << frag;
    std::ofstream(dir.file(name + ".glib")) << "Vertex st.vert\nFragment " << name << ".frag\nProgram " << name
                                            << "\nQuadXY 0 1\n";
    return runGlimmer({"check", dir.file(name + ".glib"), "--backend", "osmesa", "-I", cliData("")});
}

TEST(CliUnsetUniforms, EachIsNamedWithItsDeclarationAndWhereItsValueGoes) {
    const std::string script = cliData("unset_uniforms.glib");
    auto r = runGlimmer({"check", script, "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err,
              script + ":7:1: warning: Program Lit reads uniform float uKd (unset_uniforms.frag:5) but the script "
                       "never sets it, so it stays 0; give it a value or a slider on this Program line, e.g. "
                       "'uKd <0. 1. 1.>'\n"
                       "Program Lit uKa <0. .2 1.>\n"
                       "^\n" +
                  script + ":7:1: warning: Program Lit reads uniform vec3 uColor (unset_uniforms.frag:6) but the "
                           "script never sets it, so it stays all 0; give it a value on this Program line, e.g. "
                           "'uColor {1. 1. 1.}'\n"
                           "Program Lit uKa <0. .2 1.>\n"
                           "^\n");
}

TEST(CliUnsetUniforms, SettingThemSilencesIt) {
    TempDir dir;
    const std::string script = dir.file("set.glib");
    std::ofstream(script) << "Vertex st.vert\nFragment unset_uniforms.frag\n"
                             "Program Lit uKa <0. .2 1.> uKd <0. 1. 1.> uColor {1 1 1}\nQuadXY 0 1\n";
    auto r = runGlimmer({"check", script, "--backend", "osmesa", "-I", cliData("")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "") << r.err;
}

// What Glimmer itself feeds (Timer, the built-in noise) is never "unset".
TEST(CliUnsetUniforms, WhatGlimmerFeedsIsNotUnset) {
    TempDir dir;
    auto r = checkOneProgram(dir, "Fed",
                             "#version 330 compatibility\nuniform float Timer;\nuniform sampler2D Noise2;\n"
                             "in vec2 vST;\nvoid main() { gl_FragColor = vec4(Timer, texture(Noise2, vST).r, 0., 1.); }\n");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "") << r.err;
}

// An integer vector's example is GLIB's bracket form with one whole number a
// component.
TEST(CliUnsetUniforms, IntegerVectorsGetTheirBracketExample) {
    TempDir dir;
    auto r = checkOneProgram(dir, "Ints",
                             "#version 330 compatibility\nuniform ivec2 uA;\nuniform ivec3 uB;\nuniform ivec4 uC;\n"
                             "in vec2 vST;\nvoid main() { gl_FragColor = vec4(float(uA.x + uB.y + uC.z), 0., 0., 1.); }\n");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const char* want : {"uniform ivec2 uA (Ints.frag:2)", ", e.g. 'uA [1 1]'\n", "uniform ivec3 uB (Ints.frag:3)",
                             ", e.g. 'uB [1 1 1]'\n", "uniform ivec4 uC (Ints.frag:4)", ", e.g. 'uC [1 1 1 1]'\n"})
        EXPECT_NE(r.err.find(want), std::string::npos) << want << "\n" << r.err;
}

// No Program line can set an unsigned int: the advice is the shader's, not
// the script's (a range given to one is warned "it is not set").
TEST(CliUnsetUniforms, AnUnsignedIntIsToldToBeSetInItsShader) {
    TempDir dir;
    auto r = checkOneProgram(dir, "Uns",
                             "#version 330 compatibility\nuniform uint uN;\nuniform uvec3 uV;\n"
                             "in vec2 vST;\nvoid main() { gl_FragColor = vec4(float(uN + uV.y), 0., 0., 1.); }\n");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string script = dir.file("Uns.glib");
    EXPECT_EQ(r.err,
              script + ":3:1: warning: Program Uns reads uniform uint uN (Uns.frag:2) but the script never sets it, so "
                       "it stays 0; no GLIB form sets a uint: give it a value where the shader declares it, or declare "
                       "it int\nProgram Uns\n^\n" +
                  script + ":3:1: warning: Program Uns reads uniform uvec3 uV (Uns.frag:3) but the script never sets "
                           "it, so it stays all 0; no GLIB form sets a uvec3: give it a value where the shader declares "
                           "it, or declare it ivec3\nProgram Uns\n^\n");
}

}  // namespace
}  // namespace glimmer_cli
