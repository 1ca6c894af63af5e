// ES precision qualifiers blanked out of desktop GLSL below 1.30 (NVIDIA
// accepts them, Mesa does not): lines and columns kept, comments, strings
// and preprocessor lines left alone, 1.30 and later untouched.
#include <string>

#include <gtest/gtest.h>

#include "shader/precision_strip.h"

using namespace glimmer;

namespace {

TEST(PrecisionStrip, StatementAndQualifiersBecomeSpacesInPlace) {
    std::string in = "#version 120\nprecision highp float;\nvarying mediump vec2 vST;\nlowp float f(lowp float x);\n";
    auto r = stripPrecisionQualifiers(in);
    EXPECT_EQ(r.text, "#version 120\n                      \nvarying         vec2 vST;\n     float f(     float x);\n");
    EXPECT_EQ(r.text.size(), in.size());
    EXPECT_EQ(r.firstLine, 2);
}

TEST(PrecisionStrip, NoVersionIs110) {
    auto r = stripPrecisionQualifiers("// a comment\nuniform highp float u;\n");
    EXPECT_EQ(r.text, "// a comment\nuniform       float u;\n");
    EXPECT_EQ(r.firstLine, 2);
}

TEST(PrecisionStrip, GlslWithPrecisionIsLeftAlone) {
    for (const char* v : {"#version 130\n", "#version 330 compatibility\n", "  #version 450\n"}) {
        std::string in = std::string(v) + "precision highp float;\nhighp vec2 a;\n";
        auto r = stripPrecisionQualifiers(in);
        EXPECT_EQ(r.text, in) << v;
        EXPECT_FALSE(r.changed()) << v;
    }
}

TEST(PrecisionStrip, CommentsPreprocessorAndOtherWordsAreLeftAlone) {
    std::string in = "#version 120\n/* highp\n precision */ // lowp\n#define Q mediump\nfloat highpass, lowp2;\n";
    auto r = stripPrecisionQualifiers(in);
    EXPECT_EQ(r.text, in);
    EXPECT_FALSE(r.changed());
}

TEST(PrecisionStrip, LinesAfterAMultiLineCommentCountRight) {
    auto r = stripPrecisionQualifiers("#version 110\n/* one\ntwo */\nprecision\n  mediump float;\nfloat x;\n");
    EXPECT_EQ(r.text, "#version 110\n/* one\ntwo */\n         \n                \nfloat x;\n");
    EXPECT_EQ(r.firstLine, 4);
}

}  // namespace
