// The rewrite a watch makes of a shader (shader/watch_rewrite.h): where the
// capture goes, what the outputs become, and every refusal's words. What
// the rewritten text draws is checked against hand-edited shaders in
// tests/cli/watch_test.cpp.
#include <gtest/gtest.h>

#include "shader/glsl_scan.h"
#include "shader/watch_rewrite.h"

namespace glimmer {
namespace {

// The watched line of the rewritten text (lines keep their numbers).
std::string lineAfter(const WatchedStage& w, int line) { return std::string(lineOf(w.text, line)); }

const char* const kBloom = R"(#version 330 compatibility
uniform sampler2D BlurUnit;
uniform float uAdd;
in vec2 vST;
void main( )
{
    vec3 rgbblur = texture( BlurUnit, vST ).rgb;   // the blurred picture
    gl_FragColor = vec4( uAdd*rgbblur, 1. );
}
)";

TEST(WatchRewrite, CaptureGoesRightAfterTheStatementOnTheLine) {
    WatchedStage w = watchFragment(kBloom, 7, "rgbblur");
    ASSERT_TRUE(w.ok) << w.error;
    EXPECT_EQ(lineAfter(w, 7), "    vec3 rgbblur = texture( BlurUnit, vST ).rgb; glimmer_watch_store(rgbblur);   // the blurred picture");
    // Every line keeps its number: the shader's own lines are where they were.
    EXPECT_EQ(lineAfter(w, 8), "    glimmer_watch_FragColor = vec4( uAdd*rgbblur, 1. );");
    EXPECT_NE(lineAfter(w, 5).find("void glimmer_watched_main( )"), std::string::npos);
    EXPECT_EQ(lineAfter(w, 5).rfind("highp vec4 glimmer_watch_v;", 0), 0u) << "helpers start the first function's line";
    // The two outputs, at locations 0 and 1, and the new main after the file.
    EXPECT_NE(w.text.find("layout(location = 0) out highp vec4 glimmer_watch_value;\n"
                          "layout(location = 1) out highp vec4 glimmer_watch_info;\n"
                          "void main() { glimmer_watch_n = 0.; glimmer_watched_main(); glimmer_watch_value = "
                          "glimmer_watch_v; glimmer_watch_info = vec4(1., glimmer_watch_n * 0.25, glimmer_watch_k / 3., 1.); }\n"),
              std::string::npos);
    EXPECT_EQ(std::count(w.text.begin(), w.text.end(), '\n'), std::count(kBloom, kBloom + strlen(kBloom), '\n') + 3);
}

// Line `shown` of `src` with `expression` watched at `line`; the refusal
// when there is one.
std::string watchedLine(std::string_view src, int line, std::string_view expression, int shown) {
    WatchedStage w = watchFragment(src, line, expression);
    return w.ok ? lineAfter(w, shown) : "refused: " + w.error;
}

TEST(WatchRewrite, AStatementOverSeveralLinesIsWatchedWhereItEnds) {
    const char* src = "void main() {\n  float a = 1. +\n     2.;\n  gl_FragColor = vec4(a);\n}\n";
    EXPECT_EQ(watchedLine(src, 2, "a", 3), "     2.; glimmer_watch_store(a);");
}

// Issue 38: a do's `while (...)` ends its statement; it is no loop header
// whose body gets braces. One line, its body a lone statement or a block.
TEST(WatchRewrite, ADoWhileOnOneLineIsWatchedAfterItsWhile) {
    EXPECT_EQ(watchedLine("void main() {\n  float x = 0.;\n  do x += 0.5; while (x < 0.);\n  gl_FragColor = vec4(x);\n}\n",
                          3, "x", 3),
              "  do x += 0.5; while (x < 0.); glimmer_watch_store(x);");
    EXPECT_EQ(watchedLine("void main() {\n  float x = 0.;\n  do { x += 0.5; } while (x < 1.);\n  gl_FragColor = vec4(x);\n}\n",
                          3, "x", 3),
              "  do { x += 0.5; } while (x < 1.); glimmer_watch_store(x);");
    // The body on its own line is still watched inside the loop, braced.
    EXPECT_EQ(watchedLine("void main() {\n  float x = 0.;\n  do\n    x += 0.5;\n  while (x < 1.);\n  gl_FragColor = vec4(x);\n}\n",
                          4, "x", 4),
              "    { x += 0.5; glimmer_watch_store(x); }");
    // A plain while after a finished do-while is a loop again.
    EXPECT_EQ(watchedLine("void main() {\n  float x = 0.;\n  do x += 0.5; while (x < 0.);\n  while (x < 2.)\n    x += 1.;\n"
                          "  gl_FragColor = vec4(x);\n}\n",
                          5, "x", 5),
              "    { x += 1.; glimmer_watch_store(x); }");
}

// Issue 38: every statement form the grammar allows on one line is watched
// where it runs, or refused with the real reason.
TEST(WatchRewrite, EveryStatementFormOnOneLine) {
    auto one = [](const char* statement, const char* expression) {
        const std::string src = std::string("void main() {\n  float x = 0.; int i = 1;\n") + statement +
                                "\n  gl_FragColor = vec4(x);\n}\n";
        return watchedLine(src, 3, expression, 3);
    };
    EXPECT_EQ(one("  for(;;) x += 1.;", "x"), "  for(;;) { x += 1.; glimmer_watch_store(x); }");
    EXPECT_EQ(one("  while (x < 1.) x += 0.5;", "x"), "  while (x < 1.) { x += 0.5; glimmer_watch_store(x); }");
    EXPECT_EQ(one("  do x += 0.5; while (x < 0.);", "x"), "  do x += 0.5; while (x < 0.); glimmer_watch_store(x);");
    // Whichever branch runs, the line ran: each branch on the line is watched.
    EXPECT_EQ(one("  if (x > 0.) x = 1.; else x = 2.;", "x"),
              "  if (x > 0.) { x = 1.; glimmer_watch_store(x); } else { x = 2.; glimmer_watch_store(x); }");
    EXPECT_EQ(one("  if (x > 0.) x = 1.; else if (i > 0) return; else x = 3.;", "x"),
              "  if (x > 0.) { x = 1.; glimmer_watch_store(x); } else if (i > 0) {  glimmer_watch_store(x); return; } "
              "else { x = 3.; glimmer_watch_store(x); }");
    EXPECT_EQ(one("  if (x > 0.) { x = 1.; } else x = 2.;", "x"),
              "  if (x > 0.) { x = 1.;  glimmer_watch_store(x);} else { x = 2.; glimmer_watch_store(x); }");
    // An if/else over two lines: only the line's own branch.
    EXPECT_EQ(watchedLine("void main() {\n  float x = 0.;\n  if (x > 0.) x = 1.;\n  else x = 2.;\n  gl_FragColor = vec4(x);\n}\n",
                          4, "x", 3),
              "  if (x > 0.) x = 1.;");
    EXPECT_EQ(one("  i = x > 0. ? 1 : 2;", "i"), "  i = x > 0. ? 1 : 2; glimmer_watch_store(i);");
}

TEST(WatchRewrite, ASwitchsCasesAreWatchedAndALabelAloneIsRefused) {
    const char* src = "void main() {\n  int i = 1; float x = 0.;\n  switch (i) {\n  case 0: x = 1.; break;\n  case 1:\n"
                      "    x = 2.;\n  default: return;\n  }\n  gl_FragColor = vec4(x);\n}\n";
    EXPECT_EQ(watchedLine(src, 4, "x", 4), "  case 0: x = 1.;  glimmer_watch_store(x); break;");
    EXPECT_EQ(watchedLine(src, 6, "x", 6), "    x = 2.; glimmer_watch_store(x);");
    // The jump after a label is watched before it leaves, as any jump.
    EXPECT_EQ(watchedLine(src, 7, "x", 7), "  default:  glimmer_watch_store(x); return;");
    EXPECT_EQ(watchedLine(src, 5, "x", 5),
              "refused: the line ends with a case label, which runs nothing: watch the line of a statement after it");
}

TEST(WatchRewrite, ALoneBodyOfAnIfOrLoopGetsBraces) {
    const char* src = "void main() {\n  float s = 0.;\n  for (int i = 0; i < 4; i++)\n    s += float(i);\n"
                      "  if (s > 1.) s = 1.;\n  gl_FragColor = vec4(s);\n}\n";
    EXPECT_EQ(watchedLine(src, 4, "i", 4), "    { s += float(i); glimmer_watch_store(i); }");
    EXPECT_EQ(watchedLine(src, 5, "s", 5), "  if (s > 1.) { s = 1.; glimmer_watch_store(s); }");
    // The ';' of a for header ends no statement: the loop's block is watched.
    EXPECT_EQ(watchedLine("void main() {\n  for (int i = 0;\n       i < 2; i++) {\n    gl_FragColor = vec4(0.);\n  }\n}\n",
                          2, "i", 3),
              "       i < 2; i++) { glimmer_watch_store(i);");
}

TEST(WatchRewrite, AReturnOrDiscardIsWatchedBeforeItLeaves) {
    const char* src = "float f(float x) {\n  float y = x * 2.;\n  return y;\n}\n"
                      "void main() {\n  if (f(1.) > 3.) discard;\n  gl_FragColor = vec4(1.);\n}\n";
    EXPECT_EQ(watchedLine(src, 3, "y", 3), "   glimmer_watch_store(y); return y;");
    EXPECT_EQ(watchedLine(src, 6, "f(1.)", 6), "  if (f(1.) > 3.) {  glimmer_watch_store(f(1.)); discard; }");
}

TEST(WatchRewrite, BracesOnTheLineWatchTheBlockStartOrEnd) {
    const char* src = "void main()\n{\n  vec3 c = vec3(0.);\n  for (int i = 0; i < 3; i++) {\n    c += vec3(1.);\n  }\n"
                      "  gl_FragColor = vec4(c, 1.);\n}\n";
    EXPECT_EQ(watchedLine(src, 4, "i", 4), "  for (int i = 0; i < 3; i++) { glimmer_watch_store(i);");
    EXPECT_EQ(watchedLine(src, 6, "c", 6), "   glimmer_watch_store(c);}");
    EXPECT_EQ(watchedLine(src, 8, "c", 8), " glimmer_watch_store(c); }");
    // The line that opens the function: the value as it starts, the lines
    // after it where they were (issue 40's sampled mutant watch_rewrite.cpp:332
    // ate the newline after the brace, moving every later line up one).
    EXPECT_EQ(watchedLine(src, 2, "gl_FragCoord", 2), "{ glimmer_watch_store(gl_FragCoord);");
    EXPECT_EQ(watchedLine(src, 2, "gl_FragCoord", 3), "  vec3 c = vec3(0.);");
}

TEST(WatchRewrite, OwnOutputsBecomeGlobalsAndOldShadersUseFragData) {
    const char* modern = "#version 330 core\nlayout(location = 0) out vec4 color;\nvoid f(out float x) { x = 1.; }\n"
                         "void main() {\n  float x; f(x);\n  color = vec4(x);\n}\n";
    WatchedStage w = watchFragment(modern, 5, "x");
    ASSERT_TRUE(w.ok) << w.error;
    EXPECT_EQ(lineAfter(w, 2), std::string(25, ' ') + "vec4 color;");
    EXPECT_NE(lineAfter(w, 3).find("void f(out float x)"), std::string::npos) << "a parameter's out stays";
    const char* old = "#version 120\nvoid main() {\n  float v = 0.5;\n  gl_FragData[0] = vec4(v);\n}\n";
    WatchedStage o = watchFragment(old, 3, "v");
    ASSERT_TRUE(o.ok) << o.error;
    EXPECT_EQ(lineAfter(o, 4), "  glimmer_watch_FragData[0] = vec4(v);");
    EXPECT_NE(o.text.find("gl_FragData[0] = glimmer_watch_v; gl_FragData[1] = vec4(1., glimmer_watch_n * 0.25, "
                          "glimmer_watch_k / 3., 1.); }"), std::string::npos);
    EXPECT_EQ(o.text.find("uint"), std::string::npos) << "GLSL 1.20 has no uint";
    EXPECT_EQ(o.text.find("highp"), std::string::npos) << "nor precision qualifiers";
}

TEST(WatchRewrite, AVertexWatchPassesTheValueToTheFragmentStage) {
    const char* vert = "#version 330 compatibility\nout vec2 vST;\nvoid main() {\n  vST = gl_MultiTexCoord0.st;\n"
                       "  gl_Position = ftransform();\n}\n";
    WatchedStage v = watchVertex(vert, 4, "vST");
    ASSERT_TRUE(v.ok) << v.error;
    EXPECT_EQ(lineAfter(v, 4), "  vST = gl_MultiTexCoord0.st; glimmer_watch_store(vST);");
    EXPECT_NE(v.text.find("out highp vec4 glimmer_watch_vary;\nout highp vec2 glimmer_watch_vinfo;\n"), std::string::npos);
    EXPECT_EQ(lineAfter(v, 2), "out vec2 vST;") << "a vertex stage's outputs stay outputs";
    WatchedStage f = watchFragmentOfVertex(kBloom);
    ASSERT_TRUE(f.ok) << f.error;
    EXPECT_NE(f.text.find("in highp vec4 glimmer_watch_vary;\nin highp vec2 glimmer_watch_vinfo;\n"), std::string::npos);
    EXPECT_NE(f.text.find("glimmer_watch_value = glimmer_watch_vary; glimmer_watch_info = vec4(1., glimmer_watch_vinfo * vec2(0.25, 1. / 3.), 1.);"),
              std::string::npos);
}

TEST(WatchRewrite, RefusalsSayWhy) {
    auto error = [](std::string_view src, int line, std::string_view e) {
        WatchedStage w = watchFragment(src, line, e);
        EXPECT_FALSE(w.ok);
        return std::to_string(w.column) + ": " + w.error;
    };
    EXPECT_EQ(error(kBloom, 2, "uAdd"),
              "1: line 2 is outside any function: a watch goes on a line inside a function's body, such as main's");
    EXPECT_EQ(error(kBloom, 40, "uAdd"), "0: the shader has 9 lines; there is no line 40");
    EXPECT_EQ(error("void main() {\n\n  // nothing\n}\n", 3, "x"),
              "1: line 3 holds no statement (it is blank, a comment or a directive): watch a line with one");
    EXPECT_EQ(error(kBloom, 7, "a; discard"), "0: a watch takes one expression, and ';' cannot be in one");
    EXPECT_EQ(error(kBloom, 7, "f(a"), "0: the expression's brackets do not balance (a '(' never closes)");
    EXPECT_EQ(error(kBloom, 7, "  "), "0: the expression to watch is empty");
    EXPECT_EQ(error(kBloom, 7, std::string(201, 'a')), "0: the expression is 201 characters long; a watch takes at most 200");
    EXPECT_EQ(error("float f() { return 1.; }\n", 1, "x"), "25: the shader has no main function to watch");
}

TEST(WatchRewrite, SpecsParseInBothForms) {
    WatchSpec s;
    std::string why;
    ASSERT_TRUE(parseWatchSpec("bloom.frag:12:rgb + uAdd*rgbblur", s, why)) << why;
    EXPECT_EQ(s.file, "bloom.frag");
    EXPECT_EQ(s.line, 12);
    EXPECT_EQ(s.expression, "rgb + uAdd*rgbblur");
    ASSERT_TRUE(parseWatchSpec("C:/class/bloom.frag:7 v.x ", s, why)) << why;
    EXPECT_EQ(s.file, "C:/class/bloom.frag");
    EXPECT_EQ(s.line, 7);
    EXPECT_EQ(s.expression, "v.x");
    EXPECT_FALSE(parseWatchSpec("bloom.frag:rgb", s, why));
    EXPECT_EQ(why, "'bloom.frag:rgb' is not FILE:LINE:EXPRESSION (for example bloom.frag:12:rgbblur)");
    EXPECT_FALSE(parseWatchSpec("bloom.frag:0:rgb", s, why));
    EXPECT_EQ(why, "the line number 0 is not a line of a shader");
    EXPECT_FALSE(parseWatchSpec("bloom.frag:99999999999999999999:rgb", s, why));
    EXPECT_EQ(why, "the line number 99999999999999999999 is not a line of a shader");
}

TEST(WatchRewrite, HostileTextsGetAnAnswer) {
    // A 30,000-character line, unclosed comments and braces: an answer, no crash.
    std::string longLine = "void main() { float a = 0.;" + std::string(30000, ' ') + "a += 1.; }\n";
    EXPECT_TRUE(watchFragment(longLine, 1, "a").ok);
    EXPECT_FALSE(watchFragment("void main() { /* never closed\n float a;\n", 2, "a").ok);
    EXPECT_FALSE(watchFragment("void main() {\n float a = 1.\n", 2, "a").ok);
    EXPECT_FALSE(watchFragment("", 1, "a").ok);
}

}  // namespace
}  // namespace glimmer
