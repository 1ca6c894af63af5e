// Logical lines, comments, and token shapes, checked both on the lexer itself
// and through parseScript, where the locations end up in the parse tree.
#include "lang/lexer.h"

#include <gtest/gtest.h>

#include "lang_test_util.h"

namespace glimmer {
namespace {

using test::dump;
using test::loc;
using test::messages;
using test::parse;
using Strings = std::vector<std::string>;

TEST(Lexer, BackslashJoinsTheNextLineAndTokensKeepOriginalLocations) {
    auto p = parse("Program P \\\n  uA 1 \\\n  uB <0 1 2>\nSphere\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1 'uB' <0 1 2>", "Sphere@4:1"}));
    ASSERT_EQ(p.script.commands.size(), 2u);
    const auto& args = p.script.commands[0].args;
    ASSERT_EQ(args.size(), 5u);
    EXPECT_EQ(loc(args[0].loc), "1:9");
    EXPECT_EQ(loc(args[1].loc), "2:3");
    EXPECT_EQ(loc(args[2].loc), "2:6");
    EXPECT_EQ(loc(args[3].loc), "3:3");
    EXPECT_EQ(loc(args[4].loc), "3:6");
    EXPECT_EQ(loc(args[4].items[2].loc), "3:11");
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, CrlfEndingsAfterTheBackslash) {
    auto p = parse("##OpenGL GLIB\r\nProgram P \\\r\n\tuA 1\r\nSphere 2\r\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@2:1 'P' 'uA' 1", "Sphere@4:1 2"}));
    ASSERT_EQ(p.script.commands.size(), 2u);
    ASSERT_EQ(p.script.commands[0].args.size(), 3u);
    EXPECT_EQ(p.script.commands[0].args[1].text, "uA");  // no '\r' glued to anything
    EXPECT_EQ(loc(p.script.commands[0].args[1].loc), "3:2");
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, TrailingSpacesAndTabsAfterTheBackslash) {
    auto p = parse("Program P \\ \t \r\n uA 1\\\t\n uB 2\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1 'uB' 2"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, BlankLineAfterTheLastBackslashEndsTheCommand) {
    auto p = parse("Program P \\\r\n uA 1 \\\r\n\r\nSphere\r\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1", "Sphere@4:1"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, BackslashGluedToAWord) {
    auto p = parse("Program P\\\nuA 1");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1"}));
}

TEST(Lexer, BackslashOnTheLastLineOfTheFile) {
    auto p = parse("Sphere 1 \\");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@1:1 1"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, NoFinalNewline) {
    auto p = parse("Clear\nQuadXY .2 3.");
    ASSERT_EQ(dump(p.script), (Strings{"Clear@1:1", "QuadXY@2:1 0.2 3"}));
    ASSERT_EQ(p.script.commands.size(), 2u);
    ASSERT_EQ(p.script.commands[1].args.size(), 2u);
    EXPECT_EQ(p.script.commands[1].args[1].text, "3.");
}

TEST(Lexer, TabsCountAsOneColumn) {
    auto p = parse("\t Translate\t1  \t2 3\n");
    ASSERT_EQ(p.script.commands.size(), 1u);
    const Command& c = p.script.commands[0];
    EXPECT_EQ(loc(c.loc), "1:3");
    ASSERT_EQ(c.args.size(), 3u);
    EXPECT_EQ(loc(c.args[0].loc), "1:13");
    EXPECT_EQ(loc(c.args[1].loc), "1:17");
    EXPECT_EQ(loc(c.args[2].loc), "1:19");
}

TEST(Lexer, HashAndDoubleSlashComments) {
    auto p = parse("##OpenGL GLIB\n"
                   "# a comment line\n"
                   "   // an indented one\n"
                   "Scale 2 # the rest is ignored <\n"
                   "Scale 3// also { ignored\n"
                   "Sphere#\n");
    ASSERT_EQ(dump(p.script), (Strings{"Scale@4:1 2", "Scale@5:1 3", "Sphere@6:1"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, BackslashInsideACommentDoesNotContinue) {
    auto p = parse("Sphere # not a continuation \\\nBox\n");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@1:1", "Box@2:1"}));
}

TEST(Lexer, BackslashBeforeACommentContinues) {
    auto p = parse("Program P \\ # uniforms follow\n uA 1\n");
    ASSERT_EQ(dump(p.script), (Strings{"Program@1:1 'P' 'uA' 1"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, ByteOrderMarkBeforeTheFirstLine) {
    auto p = parse("\xEF\xBB\xBFSphere 2\n");
    ASSERT_EQ(dump(p.script), (Strings{"Sphere@1:4 2"}));
    // Read as nothing, and said in a note (issue 29), not a warning.
    ASSERT_EQ(p.diags.all().size(), 1u);
    EXPECT_EQ(p.diags.all()[0].severity, Severity::Note);
    EXPECT_EQ(p.diags.all()[0].loc.line, 1);
}

TEST(Lexer, LogicalLinesSkipBlankAndCommentOnlyLines) {
    auto lines = lexScript("\n# c\n  \t\nA b \\\n\nC\n");
    ASSERT_EQ(lines.size(), 2u);
    ASSERT_EQ(lines[0].tokens.size(), 2u);
    EXPECT_EQ(lines[0].tokens[0].text, "A");
    EXPECT_EQ(loc(lines[0].tokens[1].loc), "4:3");
    ASSERT_EQ(lines[0].segments.size(), 2u);
    EXPECT_EQ(lines[0].segments[0].text, "A b ");
    EXPECT_EQ(lines[0].segments[1].line, 5);
    EXPECT_EQ(lines[1].tokens[0].text, "C");
    EXPECT_EQ(loc(lines[1].tokens[0].loc), "6:1");
}

TEST(Lexer, NumberShapes) {
    auto toks = lexScript("x 0. .5 -1. 70. +2 1e3 -.25 007\n")[0].tokens;
    ASSERT_EQ(toks.size(), 9u);
    std::vector<double> want{0, .5, -1, 70, 2, 1000, -.25, 7};
    for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(toks[i + 1].kind, Token::Kind::Number) << toks[i + 1].text;
        EXPECT_EQ(toks[i + 1].number, want[i]) << toks[i + 1].text;
        EXPECT_EQ(toks[i + 1].issue, Token::NumberIssue::None) << toks[i + 1].text;
    }
    EXPECT_EQ(toks[5].text, "+2");
}

TEST(Lexer, WordShapes) {
    auto toks = lexScript("x grid.bmp true +x -z . - 2d.bmp 1.obj ../textures/a.bmp inf 0x10\n")[0].tokens;
    Strings words;
    for (size_t i = 1; i < toks.size(); ++i) {
        EXPECT_EQ(toks[i].kind, Token::Kind::Word) << toks[i].text;
        words.push_back(toks[i].text);
    }
    EXPECT_EQ(words, (Strings{"grid.bmp", "true", "+x", "-z", ".", "-", "2d.bmp", "1.obj", "../textures/a.bmp",
                              "inf", "0x10"}));
}

TEST(Lexer, MalformedNumbersAreReadAsTheirLongestPrefix) {
    auto toks = lexScript("x 4.8. 1.. 1.2.3 5-\n")[0].tokens;
    ASSERT_EQ(toks.size(), 5u);
    std::vector<double> want{4.8, 1, 1.2, 5};
    for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(toks[i + 1].kind, Token::Kind::Number) << toks[i + 1].text;
        EXPECT_EQ(toks[i + 1].number, want[i]) << toks[i + 1].text;
        EXPECT_EQ(toks[i + 1].issue, Token::NumberIssue::Malformed) << toks[i + 1].text;
    }
}

TEST(Lexer, WordsEndAtBracketsAndCommas) {
    auto p = parse("Color{1,0,.5}\nProgram P u<0,1,2>v[a,b]\n");
    ASSERT_EQ(dump(p.script), (Strings{"Color@1:1 {1 0 0.5}", "Program@2:1 'P' 'u' <0 1 2> 'v' ['a' 'b']"}));
    ASSERT_EQ(p.script.commands.size(), 2u);
    EXPECT_EQ(p.script.commands[0].spelled, "Color");
    EXPECT_EQ(loc(p.script.commands[0].args[0].loc), "1:6");
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, CommasSeparateArgumentsOutsideGroupsToo) {
    auto p = parse("Translate 1, 2 ,3\n");
    ASSERT_EQ(dump(p.script), (Strings{"Translate@1:1 1 2 3"}));
    EXPECT_TRUE(p.diags.all().empty());
}

TEST(Lexer, ClosingBracketFor) {
    EXPECT_EQ(closingBracket('<'), '>');
    EXPECT_EQ(closingBracket('{'), '}');
    EXPECT_EQ(closingBracket('['), ']');
    EXPECT_EQ(closingBracket('('), 0);
}

}  // namespace
}  // namespace glimmer
