// Uniform initialisers taken out of a shader for GLSL ES 3.00
// (shader/uniform_initializers.h): values read, places kept, text blanked.
#include "shader/uniform_initializers.h"

#include <gtest/gtest.h>

#include <clocale>

namespace glimmer {
namespace {

TEST(UniformInitializers, NumbersAndConstructorsAreReadAndBlanked) {
    const std::string text =
        "#version 120\n"
        "uniform float uY0 = 1.;\n"
        "uniform vec3 uTint = vec3(0., .5, 1.), uOther;\n"
        "uniform lowp vec4 uAll = vec4(.25);\n"
        "uniform int uN = -3, uM = 2;\n"
        "uniform bool uOn = true;\n"
        "uniform float uPlain;\n";
    UniformInitializers r = takeUniformInitializers(text);
    ASSERT_EQ(r.values.size(), 6u);
    EXPECT_TRUE(r.unreadable.empty());
    EXPECT_EQ(r.values[0].name, "uY0");
    EXPECT_EQ(r.values[0].type, "float");
    EXPECT_EQ(r.values[0].values, std::vector<float>({1.f}));
    EXPECT_EQ(r.values[0].line, 2);
    EXPECT_EQ(r.values[0].col, 21);
    EXPECT_EQ(r.values[1].name, "uTint");
    EXPECT_EQ(r.values[1].values, std::vector<float>({0.f, .5f, 1.f}));
    EXPECT_EQ(r.values[2].name, "uAll");
    EXPECT_EQ(r.values[2].type, "vec4");
    EXPECT_EQ(r.values[2].values, std::vector<float>(4, .25f));
    EXPECT_EQ(r.values[3].name, "uN");
    EXPECT_EQ(r.values[3].values, std::vector<float>({-3.f}));
    EXPECT_EQ(r.values[4].name, "uM");
    EXPECT_EQ(r.values[4].type, "int");
    EXPECT_EQ(r.values[5].values, std::vector<float>({1.f}));
    EXPECT_EQ(r.text,
              "#version 120\n"
              "uniform float uY0     ;\n"
              "uniform vec3 uTint                   , uOther;\n"
              "uniform lowp vec4 uAll            ;\n"
              "uniform int uN     , uM    ;\n"
              "uniform bool uOn       ;\n"
              "uniform float uPlain;\n");
}

// A literal's suffix (GLSL 1.20's f, 1.30's u) is one letter, not part of its
// value: 1.25f is 1.25 and 3u is 3 (issue 40: two letters dropped made them
// 1. and nothing).
TEST(UniformInitializers, ASuffixIsNotPartOfTheValue) {
    UniformInitializers r = takeUniformInitializers("uniform float uF = 1.25f;\nuniform uint uU = 3u;\n"
                                                    "uniform vec2 uV = vec2(.5F, 2.f);\n");
    ASSERT_EQ(r.values.size(), 3u);
    EXPECT_TRUE(r.unreadable.empty());
    EXPECT_EQ(r.values[0].values, std::vector<float>({1.25f}));
    EXPECT_EQ(r.values[1].values, std::vector<float>({3.f}));
    EXPECT_EQ(r.values[2].values, std::vector<float>({.5f, 2.f}));
}

// Read the same in a decimal-comma locale (.ci/run runs every test program
// again in German): strtof would stop at the '.'.
TEST(UniformInitializers, ValuesDoNotDependOnTheLocale) {
    const char* before = std::setlocale(LC_NUMERIC, nullptr);
    const std::string saved = before ? before : "C";
    const bool german = std::setlocale(LC_NUMERIC, "de_DE.UTF-8") != nullptr;
    UniformInitializers r = takeUniformInitializers("uniform vec2 v = vec2(0.5, -1.25);\n");
    std::setlocale(LC_NUMERIC, saved.c_str());
    if (!german) GTEST_SKIP() << "no de_DE.UTF-8 locale on this machine (tools/install-deps.sh makes it)";
    ASSERT_EQ(r.values.size(), 1u);
    EXPECT_EQ(r.values[0].values, std::vector<float>({.5f, -1.25f}));
}

TEST(UniformInitializers, CommentsLocalsAndDirectivesAreLeftAlone) {
    const std::string text =
        "// uniform float a = 1.;\n"
        "/* uniform float b = 2.; */\n"
        "#define uniform_x 3\n"
        "void main() { float uniformish = 1.; }\n";
    UniformInitializers r = takeUniformInitializers(text);
    EXPECT_TRUE(r.values.empty());
    EXPECT_TRUE(r.unreadable.empty());
    EXPECT_EQ(r.text, text);
}

TEST(UniformInitializers, AnExpressionOrArrayIsUnreadableWithItsPlace) {
    UniformInitializers r = takeUniformInitializers("uniform float k = 2. * 3.;\nuniform float a[2] = float[2](1., 2.);\n"
                                                    "uniform vec2 v = vec3(1., 2., 3.);\n");
    EXPECT_TRUE(r.values.empty());
    ASSERT_EQ(r.unreadable.size(), 3u);
    EXPECT_EQ(r.unreadable[0].name, "k");
    EXPECT_EQ(r.unreadable[0].line, 1);
    EXPECT_EQ(r.unreadable[0].col, 19);
    EXPECT_EQ(r.unreadable[1].name, "a");
    EXPECT_EQ(r.unreadable[2].name, "v");
}

// A value over two lines keeps the line break (the lines after it keep
// their numbers), and a comment inside it is no part of the value.
TEST(UniformInitializers, AValueOverLinesKeepsItsNewlineAndSkipsItsComments) {
    UniformInitializers r = takeUniformInitializers("uniform vec3 uC = vec3(1., /* red */\n  0., 0.);\nuniform float uS;\n");
    ASSERT_EQ(r.values.size(), 1u);
    EXPECT_EQ(r.values[0].values, std::vector<float>({1.f, 0.f, 0.f}));
    EXPECT_EQ(r.values[0].col, 19);
    EXPECT_EQ(r.text, "uniform vec3 uC                     \n         ;\nuniform float uS;\n");
}

TEST(UniformInitializers, AnUnendedStatementOrBlockStopsQuietly) {
    EXPECT_TRUE(takeUniformInitializers("uniform float k = 1.").values.empty());
    EXPECT_TRUE(takeUniformInitializers("uniform Block { float x; };").values.empty());
    EXPECT_TRUE(takeUniformInitializers(std::string(100000, '(')).values.empty());
}

}  // namespace
}  // namespace glimmer
