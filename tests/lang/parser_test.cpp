#include "lang/parser.h"

#include <gtest/gtest.h>

#include "lang_test_util.h"

namespace glimmer {
namespace {

using test::dump;
using test::loc;
using test::messages;
using test::parse;
using Strings = std::vector<std::string>;

std::string formatAll(const test::Parsed& p, const std::string& text, const std::string& file = "t.glib") {
    SourceTexts src;
    src.add(file, text);
    std::string out;
    for (const Diagnostic& d : p.diags.all()) out += formatDiagnostic(d, src) + "\n";
    return out;
}

TEST(Parser, ScriptKeepsItsFileName) {
    auto p = parse("Sphere\n", "dir/x.glib");
    EXPECT_EQ(p.script.file, "dir/x.glib");
}

TEST(Parser, EmptyAndCommentOnlyScripts) {
    EXPECT_TRUE(parse("").script.commands.empty());
    auto p = parse("##OpenGL GLIB\n\n// nothing\n");
    EXPECT_TRUE(p.script.commands.empty());
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, CommandWordsAreCaseInsensitiveAndKeepTheirSpelling) {
    auto p = parse("Lookat 0 0 3  0 0 0  0 1 0\ntexture3D 4 noise.tex\nRendertoTexture 6\nscale 2\n");
    ASSERT_EQ(dump(p.script), (Strings{"LookAt@1:1 0 0 3 0 0 0 0 1 0", "Texture3D@2:1 4 'noise.tex'",
                                       "RenderToTexture@3:1 6", "Scale@4:1 2"}));
    EXPECT_EQ(p.script.commands[0].spelled, "Lookat");
    EXPECT_EQ(p.script.commands[1].spelled, "texture3D");
    EXPECT_EQ(p.script.commands[2].spelled, "RendertoTexture");
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, Aliases) {
    auto p = parse("Persp 70\nTransformBegin\nRenderTargetTexture 6 7\nTransformEnd\nRenderTargetTexture\n"
                   "glBegin triangles\nglVertex 0 0 0\nglEnd\nWireTorus\n");
    ASSERT_EQ(dump(p.script), (Strings{"Perspective@1:1 70", "PushMatrix@2:1", "RenderToTexture@3:1 6 7",
                                       "PopMatrix@4:1", "RenderToTexture@5:1", "glBegin@6:1 'triangles'",
                                       "glVertex@7:1 0 0 0", "glEnd@8:1", "WireTorus@9:1"}));
    EXPECT_EQ(p.script.commands[0].spelled, "Persp");
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, NumberArgumentsKeepTheirTextAndValue) {
    auto p = parse("Translate -1. .5 70.\n");
    ASSERT_EQ(p.script.commands.size(), 1u);
    const auto& a = p.script.commands[0].args;
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a[0].kind, Arg::Kind::Number);
    EXPECT_EQ(a[0].number, -1.0);
    EXPECT_EQ(a[0].text, "-1.");
    EXPECT_EQ(a[1].number, 0.5);
    EXPECT_EQ(a[1].text, ".5");
    EXPECT_EQ(a[2].number, 70.0);
    EXPECT_EQ(loc(a[2].loc), "1:18");
    EXPECT_FALSE(a[0].isGroup());
}

TEST(Parser, GroupKindsItemsAndLocations) {
    auto p = parse("Program P uS < 0 .1 .5> uC {0.4, 1.0, 0.95, 1.} uA [1 2 3] uB <true>\n");
    ASSERT_EQ(p.script.commands.size(), 1u);
    const auto& a = p.script.commands[0].args;
    ASSERT_EQ(a.size(), 9u);
    ASSERT_EQ(dump(p.script.commands[0]), "Program@1:1 'P' 'uS' <0 0.1 0.5> 'uC' {0.4 1 0.95 1} 'uA' [1 2 3] 'uB' <'true'>");
    EXPECT_EQ(a[2].kind, Arg::Kind::Range);
    EXPECT_EQ(a[4].kind, Arg::Kind::Color);
    EXPECT_EQ(a[6].kind, Arg::Kind::Array);
    EXPECT_EQ(a[8].kind, Arg::Kind::Range);
    EXPECT_TRUE(a[2].isGroup());
    EXPECT_EQ(loc(a[2].loc), "1:14");
    EXPECT_EQ(loc(a[2].items[0].loc), "1:16");
    EXPECT_EQ(loc(a[2].items[1].loc), "1:18");
    EXPECT_EQ(loc(a[4].loc), "1:28");
    EXPECT_EQ(loc(a[4].items[3].loc), "1:45");
    EXPECT_EQ(a[4].items[3].text, "1.");
    EXPECT_EQ(a[8].items[0].kind, Arg::Kind::Word);
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, CommasInsideGroups) {
    auto p = parse("Program P uR <0, 3, 3> uV [1,2 , 3]\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uR' <0 3 3> 'uV' [1 2 3]"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, EmptyGroup) {
    auto p = parse("Color [ ]\n");
    ASSERT_EQ(dump(p.script), (Strings{"Color@1:1 []"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, DecimalCommaInABlankSeparatedRangeIsReadAsAPointWithAWarning) {
    auto p = parse("Program P uK < 0,01 0.1 1.0 >\n");
    ASSERT_EQ(p.script.commands.size(), 1u);
    ASSERT_EQ(p.script.commands[0].args.size(), 3u);
    const Arg& r = p.script.commands[0].args[2];
    ASSERT_EQ(dump(r), "<0.01 0.1 1>");
    EXPECT_EQ(r.items[0].text, "0,01");
    EXPECT_EQ(loc(r.items[0].loc), "1:16");
    EXPECT_EQ(messages(p.diags), (Strings{"1:16: warning: decimal comma in '0,01' read as 0.01; GLIB separates values "
                                          "with commas, so write decimals with a point"}));
}

TEST(Parser, DecimalCommasInEveryKindOfGroup) {
    auto p = parse("Program P uA <0,5 1,0 2,0> uB <-1,5 0 +1,5> uC {0,5 0,25 1}\nTriangles [0,5 1,5 0] [1 1 0] [0 0 0]\n");
    EXPECT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' <0.5 1 2> 'uB' <-1.5 0 1.5> 'uC' {0.5 0.25 1}",
                                       "Triangles@2:1 [0.5 1.5 0] [1 1 0] [0 0 0]"}));
    EXPECT_EQ(p.diags.warningCount(), 9);
}

TEST(Parser, CommasThatSeparateStaySeparators) {
    // Commas alone, comma and blank, a colour that fits either way, outside a
    // group, thousands, a vertex of three: all separators, no warning.
    auto p = parse("Program P uA <0,3,3> uB <0, 3, 3> uC {1,0 0 0} uD [1,5 2]\nTranslate 1,5 2 3\n"
                   "Program Q uE <1,000,000 0 1> uF <0,5 1>\n");
    EXPECT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' <0 3 3> 'uB' <0 3 3> 'uC' {1 0 0 0} 'uD' [1 5 2]",
                                       "Translate@2:1 1 5 2 3",
                                       "Program@3:1 'Q' 'uE' <1 0 0 0 1> 'uF' <0 5 1>"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, MalformedNumbersWarnWithTheTokenAndTheValueRead) {
    std::string text = "Translate 4.8. 0 0\nColor {1.. 0. .5}\n";
    auto p = parse(text);
    ASSERT_EQ(dump(p.script), (Strings{"Translate@1:1 4.8 0 0", "Color@2:1 {1 0 0.5}"}));
    EXPECT_EQ(p.script.commands[0].args[0].text, "4.8.");
    EXPECT_EQ(messages(p.diags), (Strings{"1:11: warning: malformed number '4.8.' read as 4.8",
                                          "2:8: warning: malformed number '1..' read as 1"}));
    EXPECT_EQ(formatAll(p, text),
              "t.glib:1:11: warning: malformed number '4.8.' read as 4.8\n"
              "Translate 4.8. 0 0\n"
              "          ^\n"
              "t.glib:2:8: warning: malformed number '1..' read as 1\n"
              "Color {1.. 0. .5}\n"
              "       ^\n");
}

TEST(Parser, NumberOutOfRangeIsAnErrorAndDropsTheCommand) {
    auto p = parse("Scale 1e999\nSphere\n");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@2:1"}));
    EXPECT_EQ(messages(p.diags), (Strings{"1:7: error: number '1e999' is out of range; command 'Scale' ignored"}));
}

TEST(Parser, UnterminatedGroupIsAnErrorAtTheOpeningBracket) {
    std::string text = "Program P uA <0 1\nSphere\n";
    auto p = parse(text);
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@2:1"}));
    EXPECT_EQ(messages(p.diags), (Strings{"1:14: error: '<' is never closed (missing '>'); command 'Program' ignored"}));
    EXPECT_EQ(formatAll(p, text),
              "t.glib:1:14: error: '<' is never closed (missing '>'); command 'Program' ignored\n"
              "Program P uA <0 1\n"
              "             ^\n");
}

TEST(Parser, UnterminatedGroupDoesNotRunIntoTheNextLine) {
    auto p = parse("Color {1 0 0\n}\nBox\n");
    ASSERT_EQ(dump(p.script), (Strings{"Box@3:1"}));
    EXPECT_EQ(messages(p.diags), (Strings{"1:7: error: '{' is never closed (missing '}'); command 'Color' ignored",
                                          "2:1: warning: expected a command word, found '}'; line ignored"}));
}

TEST(Parser, NestedGroupIsAnErrorAtTheInnerBracket) {
    auto p = parse("Triangles [0 [1] 2]\nSphere\n");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@2:1"}));
    EXPECT_EQ(messages(p.diags),
              (Strings{"1:14: error: '[' inside '[...]'; groups do not nest; command 'Triangles' ignored"}));
}

TEST(Parser, MismatchedClosingBracket) {
    auto p = parse("Program P u <0 1 2}\nSphere\n");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@2:1"}));
    EXPECT_EQ(messages(p.diags),
              (Strings{"1:19: error: '}' cannot close '<' (expected '>'); command 'Program' ignored"}));
}

TEST(Parser, StrayClosingBracket) {
    auto p = parse("Scale 2 ]\nSphere\n");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@2:1"}));
    EXPECT_EQ(messages(p.diags), (Strings{"1:9: error: unexpected ']' outside a group; command 'Scale' ignored"}));
}

TEST(Parser, UnknownCommandIsWarnedAndSkipped) {
    std::string text = "Sphere\n  Foo 1 <2\nBox\n";
    auto p = parse(text);
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@1:1", "Box@3:1"}));
    EXPECT_EQ(messages(p.diags), (Strings{"2:3: warning: unknown command 'Foo'; line ignored"}));
    EXPECT_EQ(formatAll(p, text),
              "t.glib:2:3: warning: unknown command 'Foo'; line ignored\n"
              "  Foo 1 <2\n"
              "  ^\n");
}

TEST(Parser, LineStartingWithSomethingOtherThanAWord) {
    auto p = parse("3 4\n<0 1>\nBox\n");
    ASSERT_EQ(dump(p.script), (Strings{"Box@3:1"}));
    EXPECT_EQ(messages(p.diags), (Strings{"1:1: warning: expected a command word, found '3'; line ignored",
                                          "2:1: warning: expected a command word, found '<'; line ignored"}));
}

TEST(Parser, MessageBoxTakesItsTextVerbatim) {
    auto p = parse("MessageBox  Use the <slider>, then {press} 1.2.3 \\\n   to go on  # not shown\nSphere\n");
    ASSERT_EQ(p.script.commands.size(), 2u);
    const Command& m = p.script.commands[0];
    EXPECT_EQ(m.kind, CommandKind::MessageBox);
    ASSERT_EQ(m.args.size(), 1u);
    EXPECT_EQ(m.args[0].kind, Arg::Kind::Word);
    EXPECT_EQ(m.args[0].text, "Use the <slider>, then {press} 1.2.3 to go on");
    EXPECT_EQ(loc(m.args[0].loc), "1:13");
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Parser, BareMessageBoxHasNoArguments) {
    auto p = parse("MessageBox   \n");
    ASSERT_EQ(dump(p.script), (Strings{"MessageBox@1:1"}));
}

TEST(Parser, UniformsOnLinesOfTheirOwnAreAttachedToTheProgram) {
    std::string text =
        "Program SuperBlur\n"
        "\n"
        "    # the blur size\n"
        "    uHalfSize <0 0 11>\n"
        "\tImageUnit 5\n"
        "QuadXY .2 3.\n";
    auto p = parse(text);
    ASSERT_EQ(dump(p.script),
              (Strings{"Program@1:1 'SuperBlur' 'uHalfSize' <0 0 11> 'ImageUnit' 5", "QuadXY@6:1 0.2 3"}));
    ASSERT_EQ(p.script.commands.size(), 2u);
    const auto& a = p.script.commands[0].args;
    ASSERT_EQ(a.size(), 5u);
    EXPECT_EQ(loc(a[1].loc), "4:5");
    EXPECT_EQ(loc(a[2].items[2].loc), "4:20");
    EXPECT_EQ(loc(a[3].loc), "5:2");
    EXPECT_EQ(messages(p.diags),
              (Strings{"4:5: warning: uniform 'uHalfSize' is on a line of its own; taken as part of Program "
                       "'SuperBlur' (line 1); glman needs a '\\' at the end of the previous line",
                       "5:2: warning: uniform 'ImageUnit' is on a line of its own; taken as part of Program "
                       "'SuperBlur' (line 1); glman needs a '\\' at the end of the previous line"}));
    EXPECT_EQ(formatAll(p, text),
              "t.glib:4:5: warning: uniform 'uHalfSize' is on a line of its own; taken as part of Program "
              "'SuperBlur' (line 1); glman needs a '\\' at the end of the previous line\n"
              "    uHalfSize <0 0 11>\n"
              "    ^\n"
              "t.glib:5:2: warning: uniform 'ImageUnit' is on a line of its own; taken as part of Program "
              "'SuperBlur' (line 1); glman needs a '\\' at the end of the previous line\n"
              "\tImageUnit 5\n"
              "\t^\n");
}

TEST(Parser, AttachedLinesFollowAProgramThatUsedContinuations) {
    auto p = parse("Program P \\\n  uA 1 \\\n  uB 2\n  uC 3\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1 'uB' 2 'uC' 3"}));
    EXPECT_EQ(messages(p.diags),
              (Strings{"4:3: warning: uniform 'uC' is on a line of its own; taken as part of Program 'P' (line 1); "
                       "glman needs a '\\' at the end of the previous line"}));
}

TEST(Parser, AKnownCommandEndsTheAttachedLines) {
    auto p = parse("Program P\n uA 1\nSphere\n uB 2\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1", "Sphere@3:1"}));
    ASSERT_EQ(p.diags.all().size(), 2u);
    EXPECT_EQ(messages(p.diags)[1], "4:2: warning: unknown command 'uB'; line ignored");
}

TEST(Parser, AnUnknownWordAfterAnythingButAProgramIsNotAttached) {
    auto p = parse("Vertex a.vert\n uA 1\n");
    ASSERT_EQ(dump(p.script), (Strings{"Vertex@1:1 'a.vert'"}));
    EXPECT_EQ(messages(p.diags), (Strings{"2:2: warning: unknown command 'uA'; line ignored"}));
}

TEST(Parser, AttachedLineWithABadGroupIsDroppedButTheChainGoesOn) {
    auto p = parse("Program P\n uA <0 1\n uB 2\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uB' 2"}));
    EXPECT_EQ(messages(p.diags),
              (Strings{"2:2: warning: uniform 'uA' is on a line of its own; taken as part of Program 'P' (line 1); "
                       "glman needs a '\\' at the end of the previous line",
                       "2:5: error: '<' is never closed (missing '>'); line ignored",
                       "3:2: warning: uniform 'uB' is on a line of its own; taken as part of Program 'P' (line 1); "
                       "glman needs a '\\' at the end of the previous line"}));
}

TEST(Parser, AttachedLinesToAProgramWithoutAName) {
    auto p = parse("Program\n uA 1\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'uA' 1"}));
    EXPECT_EQ(messages(p.diags),
              (Strings{"2:2: warning: uniform 'uA' is on a line of its own; taken as part of Program (line 1); "
                       "glman needs a '\\' at the end of the previous line"}));
}

TEST(Parser, ADroppedProgramTakesNoAttachedLines) {
    auto p = parse("Program P ]\n uA 1\n");
    EXPECT_TRUE(p.script.commands.empty());
    EXPECT_EQ(messages(p.diags), (Strings{"1:11: error: unexpected ']' outside a group; command 'Program' ignored",
                                          "2:2: warning: unknown command 'uA'; line ignored"}));
}

TEST(Parser, EachProgramGetsItsOwnAttachedLines) {
    auto p = parse("Program A\n u1 1\nProgram B\n u2 2\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'A' 'u1' 1", "Program@3:1 'B' 'u2' 2"}));
    ASSERT_EQ(p.diags.all().size(), 2u);
    EXPECT_EQ(p.diags.all()[1].message,
              "uniform 'u2' is on a line of its own; taken as part of Program 'B' (line 3); glman needs a '\\' "
              "at the end of the previous line");
}

TEST(Parser, DiagnosticsCarryTheFileName) {
    auto p = parse("Foo\n", "scripts/x.glib");
    ASSERT_EQ(p.diags.all().size(), 1u);
    EXPECT_EQ(p.diags.all()[0].file, "scripts/x.glib");
    EXPECT_EQ(p.diags.all()[0].severity, Severity::Warning);
}

}  // namespace
}  // namespace glimmer
