// The one GLSL lexer (issue 38 item 2): every rewrite of a shader's text is
// a pass over these tokens instead of its own walk over characters.
//
// Contract:
//   - lexGlsl(text) returns tokens that tile `text` exactly: the first
//     begins at 0, each begins where the one before ended, the last ends at
//     text.size(); no token is empty. So a rewrite splices the original
//     text by offsets (applyGlslEdits) and keeps everything it did not mean
//     to change, byte for byte.
//   - Every token carries its 1-based line and 1-based column (in bytes) of
//     its first byte. A line ends at '\n'; "\r\n" is one Newline token.
//   - Linear time: each byte is looked at a bounded number of times (an
//     operator looks at most 3 bytes ahead). No recursion, no exceptions,
//     no allocation but the returned vector; every input, however long or
//     odd (NUL bytes, non-ASCII bytes, unclosed comments), gets an answer.
//   - Never a regular expression: std::regex overflowed the stack on a long
//     line (issue 30), and a student's shader is untrusted.
//
// Tokens, as the GLSL preprocessor and grammar see them:
//   Word          an identifier or keyword: [A-Za-z_][A-Za-z0-9_]*
//   Number        whole, as a C pp-number: a digit or '.' and a digit, then
//                 any letters, digits, '_' and '.', and a sign right after
//                 the exponent's 'e' (not in a 0x number): 1.0e-3, 0x1F,
//                 1u, .5f, 2.5lf. A suffix is never read as a word.
//   Punct         an operator or punctuator, longest first: <<= >>= ++ --
//                 << >> <= >= == != && || ^^ += -= *= /= %= &= |= ^= and
//                 each of ( ) [ ] { } . , ; : ? + - * / % < > = ! ~ & | ^
//   LineComment   "//" up to (not including) the end of its line.
//   BlockComment  "/*" through "*/"; one never closed runs to the end.
//   Directive     a preprocessor line: '#' first on its line (after blanks
//                 or block comments), up to (not including) the newline that
//                 ends it; a '\' before the newline continues it, and a
//                 block comment opened in it runs on whole. Comments in a
//                 directive are part of its one token.
//   Space         a run of ' ', '\t', '\r' (not one before '\n'), '\f', '\v'.
//   Newline       "\n" or "\r\n".
//   Other         one byte of anything else: '\', '"', '#' inside a line,
//                 '@', NUL, each byte of a non-ASCII character.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glimmer {

enum class GlslTokenKind : std::uint8_t { Word, Number, Punct, LineComment, BlockComment, Directive, Space, Newline, Other };

struct GlslToken {
    GlslTokenKind kind;
    size_t begin, end;  // byte offsets into the lexed text: [begin, end)
    int line, col;      // of `begin`, both 1-based
};

std::vector<GlslToken> lexGlsl(std::string_view text);

// The same tokens one at a time, for a reader that stops early (the
// #version directive near the top of a 2 MB shader): lexGlsl is this run to
// the end. `text` must outlive it.
class GlslLexer {
public:
    explicit GlslLexer(std::string_view text) : s_(text) {}
    // The next token into `t`; false (and `t` unchanged) at the text's end.
    bool next(GlslToken& t);

private:
    std::string_view s_;
    size_t i_ = 0;
    int line_ = 1;
    size_t lineBegin_ = 0;     // offset of the current line's first byte
    bool atLineStart_ = true;  // only blanks and block comments since the last newline
};

// The tokens a compiler's grammar reads: Word, Number, Punct and Other; no
// blanks, comments or directives (a rewrite that reads a directive lexes
// the whole text). Offsets, lines and columns are those of `text`.
std::vector<GlslToken> glslCodeTokens(std::string_view text);

// The code tokens of a directive's text after its '#' ("#  version 330"
// -> version, 330), offsets into `directive`; its comments and the '\' of
// each continued line left out.
std::vector<GlslToken> directiveTokens(std::string_view directive);

// Words, numbers, punctuation and anything else: what is neither blank nor
// a comment nor a directive.
inline bool isGlslCode(GlslTokenKind k) {
    return k == GlslTokenKind::Word || k == GlslTokenKind::Number || k == GlslTokenKind::Punct || k == GlslTokenKind::Other;
}

inline std::string_view tokenText(std::string_view text, const GlslToken& t) { return text.substr(t.begin, t.end - t.begin); }

// Whether token `k` of `tokens` is the word `word` / the punctuation `punct`
// (false past the end).
bool isWordToken(std::string_view text, const std::vector<GlslToken>& tokens, size_t k, std::string_view word);
bool isPunctToken(std::string_view text, const std::vector<GlslToken>& tokens, size_t k, std::string_view punct);

// For each token the index of the bracket that matches it ('(' and ')', '['
// and ']', '{' and '}'), npos for any other token or one with no match. A
// closing bracket of the wrong kind closes nothing and matches nothing.
std::vector<size_t> matchingBrackets(std::string_view text, const std::vector<GlslToken>& tokens);

// Replace `erase` bytes at `at` with `insert`.
struct GlslEdit {
    size_t at = 0;
    size_t erase = 0;
    std::string insert;
};
// The edit that turns bytes [begin, end) of `text` into spaces, its
// newlines kept, so every line and column after it stays where it was
// (what a rewrite takes out of a shader whose lines a log will name).
GlslEdit blankingEdit(std::string_view text, size_t begin, size_t end);
// `text` with `edits` made; they may come in any order, two at one offset
// keep theirs, and one that overlaps an earlier one is left out (a rewrite
// never makes such, so it is a guard, not a rule).
std::string applyGlslEdits(std::string_view text, std::vector<GlslEdit> edits);

}  // namespace glimmer
