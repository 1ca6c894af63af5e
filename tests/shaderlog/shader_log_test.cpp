// prepareSource (GSTAP prelude after #version) and mapCompilerLog (driver
// logs back to the user's file and line). Pure functions: no GL context.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gl/shader_build.h"

namespace glimmer {
namespace {

using V = std::vector<std::string>;

int countLines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

std::vector<std::string> splitLines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

// "file:line:col: severity: message"
V dump(const Diagnostics& d) {
    V out;
    for (const auto& x : d.all())
        out.push_back(x.file + ":" + std::to_string(x.loc.line) + ":" + std::to_string(x.loc.col) + ": " +
                      severityName(x.severity) + ": " + x.message);
    return out;
}

const int kPreludeLines = countLines(kGstapPrelude);

TEST(GstapPrelude, IsSixteenDefinesEndingInANewline) {
    EXPECT_EQ(kPreludeLines, 16);
    std::string p = kGstapPrelude;
    ASSERT_FALSE(p.empty());
    EXPECT_EQ(p.back(), '\n');
    for (const auto& l : splitLines(p)) EXPECT_EQ(l.rfind("#define ", 0), 0u) << l;
    EXPECT_NE(p.find("#define uModelViewProjectionMatrix gl_ModelViewProjectionMatrix\n"), std::string::npos);
    EXPECT_NE(p.find("#define aTexCoord7 gl_MultiTexCoord7\n"), std::string::npos);
}

// ---- prepareSource ------------------------------------------------------------

TEST(PrepareSource, NoPreludeLeavesTheTextAlone) {
    std::string src = "#version 330 compatibility\nvoid main() {}\n";
    PreparedSource p = prepareSource(src, "");
    EXPECT_EQ(p.text, src);
    EXPECT_EQ(p.insertedAfter, 0);
    EXPECT_EQ(p.insertedLines, 0);
    for (int i = 1; i <= 5; ++i) EXPECT_EQ(p.originalLine(i), i);
}

TEST(PrepareSource, PreludeGoesAfterVersion) {
    std::string src = "#version 330 compatibility\nuniform float uA;\nvoid main() {}\n";
    PreparedSource p = prepareSource(src, kGstapPrelude);
    EXPECT_EQ(p.text, "#version 330 compatibility\n" + std::string(kGstapPrelude) + "uniform float uA;\nvoid main() {}\n");
    EXPECT_EQ(p.insertedAfter, 1);
    EXPECT_EQ(p.insertedLines, 16);
    V lines = splitLines(p.text);
    ASSERT_EQ(lines.size(), 19u);
    EXPECT_EQ(lines[0], "#version 330 compatibility");  // #version stays first
    EXPECT_EQ(lines[1], "#define uModelViewMatrix gl_ModelViewMatrix");
    EXPECT_EQ(lines[17], "uniform float uA;");

    EXPECT_EQ(p.originalLine(1), 1);   // the #version line
    EXPECT_EQ(p.originalLine(2), 1);   // inside the prelude: blamed on the line it follows
    EXPECT_EQ(p.originalLine(17), 1);
    EXPECT_EQ(p.originalLine(18), 2);  // after it: shifted back
    EXPECT_EQ(p.originalLine(19), 3);
}

TEST(PrepareSource, VersionAfterCommentsAndBlankLines) {
    std::string src = "// blur\n\n   #version 120\nvoid main() {}\n";
    PreparedSource p = prepareSource(src, "#define A 1\n#define B 2\n");
    EXPECT_EQ(p.text, "// blur\n\n   #version 120\n#define A 1\n#define B 2\nvoid main() {}\n");
    EXPECT_EQ(p.insertedAfter, 3);
    EXPECT_EQ(p.insertedLines, 2);
    EXPECT_EQ(p.originalLine(1), 1);
    EXPECT_EQ(p.originalLine(3), 3);
    EXPECT_EQ(p.originalLine(4), 3);
    EXPECT_EQ(p.originalLine(5), 3);
    EXPECT_EQ(p.originalLine(6), 4);
}

TEST(PrepareSource, WithoutVersionThePreludeGoesOnTop) {
    std::string src = "uniform float uA;\nvoid main() {}\n";
    PreparedSource p = prepareSource(src, kGstapPrelude);
    EXPECT_EQ(p.text, std::string(kGstapPrelude) + src);
    EXPECT_EQ(p.insertedAfter, 0);
    EXPECT_EQ(p.insertedLines, 16);
    EXPECT_EQ(p.originalLine(1), 0);   // inside the prelude: no line of the user's
    EXPECT_EQ(p.originalLine(16), 0);
    EXPECT_EQ(p.originalLine(17), 1);
    EXPECT_EQ(p.originalLine(18), 2);
}

TEST(PrepareSource, VersionOnTheLastLineWithoutNewline) {
    PreparedSource p = prepareSource("// x\n#version 330", "#define A 1\n");
    EXPECT_EQ(p.text, "// x\n#version 330\n#define A 1\n");
    EXPECT_EQ(p.insertedAfter, 2);
    EXPECT_EQ(p.insertedLines, 1);
}

TEST(PrepareSource, CrLfSource) {
    std::string src = "#version 330 compatibility\r\nvoid main() {}\r\n";
    PreparedSource p = prepareSource(src, "#define A 1\n");
    EXPECT_EQ(p.text, "#version 330 compatibility\r\n#define A 1\nvoid main() {}\r\n");
    EXPECT_EQ(p.insertedAfter, 1);
    EXPECT_EQ(p.originalLine(3), 2);
}

TEST(PrepareSource, OnlyTheFirstVersionCounts) {
    // A #version in a later line (an error the compiler will report) does not
    // move the prelude down.
    std::string src = "#version 330\nvoid f();\n#version 400\n";
    PreparedSource p = prepareSource(src, "#define A 1\n");
    EXPECT_EQ(p.text, "#version 330\n#define A 1\nvoid f();\n#version 400\n");
    EXPECT_EQ(p.insertedAfter, 1);
}

// ---- mapCompilerLog -------------------------------------------------------------

const SourceLoc kFallback{9, 1};

Diagnostics mapLog(const std::string& log, const PreparedSource& src,
                   Severity defaultSeverity = Severity::Error) {
    Diagnostics d;
    mapCompilerLog(log, src, "shaders/blur.frag", "blur.glib", kFallback, defaultSeverity, d);
    return d;
}

TEST(MapCompilerLog, MesaWithoutPrelude) {
    PreparedSource src = prepareSource("#version 330\n...", "");
    Diagnostics d = mapLog(
        "0:12(5): error: `foo' undeclared\n"
        "0:3(17): warning: `x' used uninitialized\n",
        src);
    EXPECT_EQ(dump(d), (V{"shaders/blur.frag:12:5: error: `foo' undeclared",
                          "shaders/blur.frag:3:17: warning: `x' used uninitialized"}));
}

TEST(MapCompilerLog, MesaThroughThePrelude) {
    PreparedSource src = prepareSource("#version 330 compatibility\nvoid main() {\n  foo;\n}\n", kGstapPrelude);
    ASSERT_EQ(src.insertedAfter, 1);
    // Line 3 of the user's file is line 3 + 16 as compiled.
    Diagnostics d = mapLog("0:19(3): error: `foo' undeclared\n0:1(10): error: GLSL 3.30 is not supported\n", src);
    EXPECT_EQ(dump(d), (V{"shaders/blur.frag:3:3: error: `foo' undeclared",
                          "shaders/blur.frag:1:10: error: GLSL 3.30 is not supported"}));
}

TEST(MapCompilerLog, MesaInsideThePreludeBlamesTheVersionLine) {
    PreparedSource src = prepareSource("#version 330 compatibility\nvoid main() {}\n", kGstapPrelude);
    Diagnostics d = mapLog("0:7(9): error: macro redefined\n", src);
    EXPECT_EQ(dump(d), V{"shaders/blur.frag:1:9: error: macro redefined"});
}

TEST(MapCompilerLog, MesaPreprocessorMessages) {
    // glcpp writes "preprocessor error:" / "preprocessor warning:".
    PreparedSource src = prepareSource("#version 330 compatibility\n#if\nvoid main() {}\n", kGstapPrelude);
    Diagnostics d = mapLog("0:18(1): preprocessor error: #if with no expression\n"
                           "0:20(2): preprocessor warning: extra tokens\n",
                           src);
    ASSERT_EQ(d.all().size(), 2u);
    EXPECT_EQ(d.all()[0].severity, Severity::Error);
    EXPECT_EQ(d.all()[0].loc.line, 2);
    EXPECT_EQ(d.all()[0].loc.col, 1);
    EXPECT_EQ(d.all()[0].message, "#if with no expression");
    EXPECT_EQ(d.all()[1].severity, Severity::Warning);
    EXPECT_EQ(d.all()[1].loc.line, 4);
    EXPECT_EQ(d.all()[1].file, "shaders/blur.frag");
}

TEST(MapCompilerLog, NvidiaWithoutPrelude) {
    PreparedSource src = prepareSource("...", "");
    Diagnostics d = mapLog(
        "0(12) : error C1008: undefined variable \"foo\"\n"
        "0(7) : warning C7533: global variable gl_FragColor is deprecated after version 120\n",
        src);
    EXPECT_EQ(dump(d), (V{"shaders/blur.frag:12:0: error: undefined variable \"foo\"",
                          "shaders/blur.frag:7:0: warning: global variable gl_FragColor is deprecated after version 120"}));
}

TEST(MapCompilerLog, NvidiaThroughThePrelude) {
    PreparedSource src = prepareSource("#version 330 compatibility\nuniform float u;\nvoid main() {\n  foo;\n}\n",
                                       kGstapPrelude);
    Diagnostics d = mapLog("0(20) : error C1008: undefined variable \"foo\"\r\n", src);
    EXPECT_EQ(dump(d), V{"shaders/blur.frag:4:0: error: undefined variable \"foo\""});
}

TEST(MapCompilerLog, PreludeOnTopWithoutVersion) {
    PreparedSource src = prepareSource("void main() {\n  foo;\n}\n", kGstapPrelude);
    Diagnostics d = mapLog("0:18(3): error: `foo' undeclared\n0(18) : error C1008: undefined variable \"foo\"\n", src);
    EXPECT_EQ(dump(d), (V{"shaders/blur.frag:2:3: error: `foo' undeclared",
                          "shaders/blur.frag:2:0: error: undefined variable \"foo\""}));
}

TEST(MapCompilerLog, UnmatchedLinesBecomeOneDiagnosticAtTheFallback) {
    PreparedSource src = prepareSource("...", "");
    Diagnostics d = mapLog("Vertex info\n-----------\n\n   \nAn error occurred somewhere\n", src);
    EXPECT_EQ(dump(d), V{"blur.glib:9:1: error: Vertex info\n-----------\nAn error occurred somewhere"});
}

TEST(MapCompilerLog, UnmatchedUsesTheDefaultSeverityAndComesLast) {
    PreparedSource src = prepareSource("...", "");
    Diagnostics d = mapLog("WARNING: something odd\n0:2(1): warning: unused\nstill odd\n", src, Severity::Warning);
    EXPECT_EQ(dump(d), (V{"shaders/blur.frag:2:1: warning: unused",
                          "blur.glib:9:1: warning: WARNING: something odd\nstill odd"}));
}

TEST(MapCompilerLog, EmptyLogSaysNothing) {
    PreparedSource src = prepareSource("...", "");
    EXPECT_TRUE(mapLog("", src).all().empty());
    EXPECT_TRUE(mapLog("\n\n  \n", src).all().empty());
}

}  // namespace
}  // namespace glimmer

namespace glimmer {
namespace {

// std::regex recursed per character and overflowed the stack on long log
// lines; the hand parser is linear.
TEST(MapCompilerLog, HugeLinesParseWithoutRecursion) {
    const std::string huge(2000000, 'x');
    Diagnostics d;
    mapCompilerLog("0:3(7): error: " + huge + "\n" + huge + "\n", PreparedSource{}, "s.frag", "a.glib", {9, 1},
                   Severity::Error, d);
    ASSERT_EQ(d.all().size(), 2u);
    EXPECT_EQ(d.all()[0].loc.line, 3);
    EXPECT_EQ(d.all()[0].loc.col, 7);
    EXPECT_EQ(d.all()[0].message, huge);
    EXPECT_EQ(d.all()[1].file, "a.glib");
    EXPECT_EQ(d.all()[1].message, huge);
}

TEST(MapCompilerLog, LineNumbersBeyondIntAreClampedNotThrown) {
    Diagnostics d;
    mapCompilerLog("0:99999999999999999999(1): error: far\n0(88888888888888888) : warning C7: nv\n", PreparedSource{},
                   "s.frag", "a.glib", {}, Severity::Error, d);
    ASSERT_EQ(d.all().size(), 2u);
    EXPECT_EQ(d.all()[0].loc.line, 2147483647);
    EXPECT_EQ(d.all()[1].loc.line, 2147483647);
    EXPECT_EQ(d.all()[1].message, "nv");
}

TEST(MapCompilerLog, PreprocessorWordNeedsASpaceAfterIt) {
    Diagnostics d;
    mapCompilerLog("0:1(2): preprocessorerror: x\n0:1(2): preprocessor warning: y\n", PreparedSource{}, "s", "f", {},
                   Severity::Error, d);
    ASSERT_EQ(d.all().size(), 2u);
    EXPECT_EQ(d.all()[0].file, "s");
    EXPECT_EQ(d.all()[0].severity, Severity::Warning);
    EXPECT_EQ(d.all()[0].message, "y");
    EXPECT_EQ(d.all()[1].file, "f");  // the first line matched neither form
}

}  // namespace
}  // namespace glimmer
