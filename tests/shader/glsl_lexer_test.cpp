// The one GLSL lexer (shader/glsl_lexer.h): exact token lists (kind, text,
// line, column) for the inputs that tripped the hand-written scans, and the
// helpers every rewrite shares.
#include "shader/glsl_lexer.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace glimmer {
namespace {

const char* kindName(GlslTokenKind k) {
    switch (k) {
        case GlslTokenKind::Word: return "Word";
        case GlslTokenKind::Number: return "Number";
        case GlslTokenKind::Punct: return "Punct";
        case GlslTokenKind::LineComment: return "LineComment";
        case GlslTokenKind::BlockComment: return "BlockComment";
        case GlslTokenKind::Directive: return "Directive";
        case GlslTokenKind::Space: return "Space";
        case GlslTokenKind::Newline: return "Newline";
        case GlslTokenKind::Other: return "Other";
    }
    return "?";
}

// The text with bytes outside printable ASCII written \n, \r, \xHH.
std::string shown(std::string_view s) {
    std::string out;
    static const char* const kHex = "0123456789abcdef";
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (u < 0x20 || u > 0x7e) out += std::string("\\x") + kHex[u >> 4] + kHex[u & 15];
        else out += c;
    }
    return out;
}

// Every token as "Kind 'text' line:col", one a line; and the tiling checked.
std::string tokens(std::string_view text, bool withBlanks = false) {
    std::string out;
    size_t at = 0;
    for (const GlslToken& t : lexGlsl(text)) {
        EXPECT_EQ(t.begin, at) << "tokens tile the text";
        EXPECT_LT(t.begin, t.end) << "no token is empty";
        at = t.end;
        if (!withBlanks && (t.kind == GlslTokenKind::Space || t.kind == GlslTokenKind::Newline)) continue;
        out += std::string(kindName(t.kind)) + " '" + shown(tokenText(text, t)) + "' " + std::to_string(t.line) + ":" +
               std::to_string(t.col) + "\n";
    }
    EXPECT_EQ(at, text.size());
    return out;
}

TEST(GlslLexer, WordsNumbersAndOperatorsWithLinesAndColumns) {
    EXPECT_EQ(tokens("float a=1.;\n  a <<= 2;"),
              "Word 'float' 1:1\nWord 'a' 1:7\nPunct '=' 1:8\nNumber '1.' 1:9\nPunct ';' 1:11\n"
              "Word 'a' 2:3\nPunct '<<=' 2:5\nNumber '2' 2:9\nPunct ';' 2:10\n");
    EXPECT_EQ(tokens("i++&&j--||k^^l!=m"),
              "Word 'i' 1:1\nPunct '++' 1:2\nPunct '&&' 1:4\nWord 'j' 1:6\nPunct '--' 1:7\nPunct '||' 1:9\n"
              "Word 'k' 1:11\nPunct '^^' 1:12\nWord 'l' 1:14\nPunct '!=' 1:15\nWord 'm' 1:17\n");
    EXPECT_EQ(tokens("a+=b>>=c>=d"), "Word 'a' 1:1\nPunct '+=' 1:2\nWord 'b' 1:4\nPunct '>>=' 1:5\nWord 'c' 1:8\n"
                                     "Punct '>=' 1:9\nWord 'd' 1:11\n");
}

TEST(GlslLexer, NumbersOfEveryFormAreWhole) {
    EXPECT_EQ(tokens("1.0e-3 0x1F 1u .5f 2.5lf 1E+10 0XffU 07 3. v.x"),
              "Number '1.0e-3' 1:1\nNumber '0x1F' 1:8\nNumber '1u' 1:13\nNumber '.5f' 1:16\nNumber '2.5lf' 1:20\n"
              "Number '1E+10' 1:26\nNumber '0XffU' 1:32\nNumber '07' 1:38\nNumber '3.' 1:41\n"
              "Word 'v' 1:44\nPunct '.' 1:45\nWord 'x' 1:46\n");
    // A hex number's 'e' is a digit, so the '+' after it is an operator.
    EXPECT_EQ(tokens("0x1e+2"), "Number '0x1e' 1:1\nPunct '+' 1:5\nNumber '2' 1:6\n");
    EXPECT_EQ(tokens("a.5"), "Word 'a' 1:1\nNumber '.5' 1:2\n");
}

TEST(GlslLexer, CommentsAreTokensAndAnUnclosedOneRunsToTheEnd) {
    EXPECT_EQ(tokens("a // x /* y\nb /* c\n d */ e /* never"),
              "Word 'a' 1:1\nLineComment '// x /* y' 1:3\nWord 'b' 2:1\nBlockComment '/* c\\n d */' 2:3\n"
              "Word 'e' 3:7\nBlockComment '/* never' 3:9\n");
    EXPECT_EQ(tokens("a/b/*/c*/d"), "Word 'a' 1:1\nPunct '/' 1:2\nWord 'b' 1:3\nBlockComment '/*/c*/' 1:4\nWord 'd' 1:10\n");
}

TEST(GlslLexer, DirectivesAreWholeLinesWithTheirContinuationsAndComments) {
    EXPECT_EQ(tokens("  #version 330 // why\n#define F(x) \\\n  (x + 1)\nF(2)\n"),
              "Directive '#version 330 // why' 1:3\nDirective '#define F(x) \\\\n  (x + 1)' 2:1\n"
              "Word 'F' 4:1\nPunct '(' 4:2\nNumber '2' 4:3\nPunct ')' 4:4\n");
    // A block comment opened in a directive runs on whole; a "/*" after
    // "//" opens nothing.
    EXPECT_EQ(tokens("#define A 1 /* two\nlines */ + 2\n#define B 2 // see /* here\nB"),
              "Directive '#define A 1 /* two\\nlines */ + 2' 1:1\nDirective '#define B 2 // see /* here' 3:1\nWord 'B' 4:1\n");
    // '#' after a block comment on its line starts a directive; after code
    // it is a byte of nothing.
    EXPECT_EQ(tokens("/* c */ #line 5\na # b"),
              "BlockComment '/* c */' 1:1\nDirective '#line 5' 1:9\nWord 'a' 2:1\nOther '#' 2:3\nWord 'b' 2:5\n");
}

TEST(GlslLexer, CrLfIsOneNewlineAndNeverPartOfAToken) {
    EXPECT_EQ(tokens("a\r\n#if 1\r\n// c\r\nb \r", true),
              "Word 'a' 1:1\nNewline '\\r\\n' 1:2\nDirective '#if 1' 2:1\nNewline '\\r\\n' 2:6\nLineComment '// c' 3:1\n"
              "Newline '\\r\\n' 3:5\nWord 'b' 4:1\nSpace ' \\r' 4:2\n");
    // Blanks before a line's end are one Space, up to the "\r\n" or "\n".
    EXPECT_EQ(tokens("a \t \r\nb  \n", true),
              "Word 'a' 1:1\nSpace ' \\x09 ' 1:2\nNewline '\\r\\n' 1:5\nWord 'b' 2:1\nSpace '  ' 2:2\nNewline '\\n' 2:4\n");
    // A continuation before "\r\n" continues too.
    EXPECT_EQ(tokens("#define X \\\r\n 1\r\nX"), "Directive '#define X \\\\r\\n 1' 1:1\nWord 'X' 3:1\n");
}

TEST(GlslLexer, OddBytesAreOtherTokensOneByteEach) {
    EXPECT_EQ(tokens(std::string_view("a\\\nb\0c \xc3\xa9 \"s\"", 13)),
              "Word 'a' 1:1\nOther '\\' 1:2\nWord 'b' 2:1\nOther '\\x00' 2:2\nWord 'c' 2:3\nOther '\\xc3' 2:5\n"
              "Other '\\xa9' 2:6\nOther '\"' 2:8\nWord 's' 2:9\nOther '\"' 2:10\n");
    EXPECT_EQ(tokens("\\"), "Other '\\' 1:1\n");
    EXPECT_EQ(tokens("#"), "Directive '#' 1:1\n");
    EXPECT_EQ(tokens("/"), "Punct '/' 1:1\n");
    EXPECT_EQ(tokens(""), "");
}

TEST(GlslLexer, CodeTokensLeaveOutBlanksCommentsAndDirectives) {
    const std::string_view text = "#version 330\nvoid /* x */ main() { } // end";
    std::string words;
    for (const GlslToken& t : glslCodeTokens(text)) words += std::string(tokenText(text, t)) + " ";
    EXPECT_EQ(words, "void main ( ) { } ");
}

// A directive's own words: after its '#', comments and the '\' of each
// continued line left out, offsets into the directive.
TEST(GlslLexer, DirectiveTokensAreItsWordsAcrossContinuations) {
    const std::string_view d = "#  define F(x) \\\r\n  (x /* y */ + 1) \\\n// z";
    std::string words;
    for (const GlslToken& t : directiveTokens(d)) words += std::string(tokenText(d, t)) + "@" + std::to_string(t.begin) + " ";
    EXPECT_EQ(words, "define@3 F@10 (@11 x@12 )@13 (@20 x@21 +@31 1@33 )@34 ");
    EXPECT_TRUE(directiveTokens("define A").empty());  // no '#': no directive
}

TEST(GlslLexer, BracketsMatchByKind) {
    const std::string_view text = "f(a[1], {b)} )";
    const std::vector<GlslToken> code = glslCodeTokens(text);
    const std::vector<size_t> mate = matchingBrackets(text, code);
    std::string pairs;
    for (size_t k = 0; k < code.size(); ++k)
        pairs += std::string(tokenText(text, code[k])) + (mate[k] == std::string_view::npos ? "-" : std::to_string(mate[k])) + " ";
    // The ')' inside the braces closes nothing: the '(' is closed by the last one.
    EXPECT_EQ(pairs, "f- (11 a- [5 1- ]3 ,- {10 b- )- }7 )1 ");
}

TEST(GlslLexer, EditsApplyInOffsetOrderAndKeepTheRest) {
    EXPECT_EQ(applyGlslEdits("abcdef", {{4, 1, "E"}, {0, 0, "<"}, {0, 0, "["}, {2, 2, ""}}), "<[abEf");
    EXPECT_EQ(applyGlslEdits("abc", {{1, 2, "X"}, {2, 0, "overlaps"}}), "aX");
    EXPECT_EQ(applyGlslEdits("abc", {{3, 0, "!"}}), "abc!");
}

TEST(GlslLexer, ALongLineIsLinear) {
    // 2 MB on one line and 2 MB of one-line functions: an answer, quickly.
    const std::string line(2u << 20, 'a');
    EXPECT_EQ(lexGlsl(line).size(), 1u);
    std::string many;
    while (many.size() < (2u << 20)) many += "float f" + std::to_string(many.size()) + "(float x) { return x * 2.; }\n";
    const std::vector<GlslToken> t = lexGlsl(many);
    EXPECT_EQ(t.back().end, many.size());
    EXPECT_EQ(t.back().line, int(std::count(many.begin(), many.end(), '\n')));
}

}  // namespace
}  // namespace glimmer
