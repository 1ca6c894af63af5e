// The lexical layer of GLIB: physical lines are joined into logical lines
// (`\` continuations), comments are dropped, and each logical line is cut into
// tokens that remember where they stand in the original text. The lexer never
// reports anything: it records what it saw (e.g. a malformed number) in the
// token, and the parser decides whether that matters for the command at hand.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostics.h"

namespace glimmer {

struct Token {
    enum class Kind { Number, Word, Open, Close };
    enum class NumberIssue {
        None,
        Malformed,   // only a prefix of `text` is a number, e.g. "4.8." or "1.."
        OutOfRange,  // e.g. "1e999"
        DecimalComma,  // "0,01" in a group, read as 0.01 (lang/decimal_comma.h)
    };
    Kind kind = Kind::Word;
    std::string text;  // as written; for Open/Close the bracket itself
    SourceLoc loc;
    double number = 0;  // Kind::Number
    NumberIssue issue = NumberIssue::None;
};

// The piece of one physical line that belongs to a logical line, after the
// comment, the line ending and a continuation `\` were removed.
struct Segment {
    int line = 0;
    int col = 0;  // of text[0]
    std::string text;
};

struct LogicalLine {
    std::vector<Token> tokens;      // never empty
    std::vector<Segment> segments;  // lets MessageBox take its text verbatim
};

// What lexing and parsing may take, counted as tokens are made (--max-memory,
// issue 30: a 10 MB line once took 1 GB): each token is charged for itself,
// the Arg the parser makes of it and their vectors' slack, before it is kept.
struct LexBudget {
    std::uint64_t maxBytes = 0;  // 0: no bound
    std::uint64_t used = 0;      // what the tokens kept so far are charged
    SourceLoc overAt;            // the token that went past maxBytes (line 0: none did)
    bool over() const { return overAt.line > 0; }
};
// The bytes one token of `textBytes` characters is charged.
std::uint64_t tokenCharge(size_t textBytes);

// Logical lines that hold at least one token, in order. With a budget,
// lexing stops at the token that would take `used` past `maxBytes`.
std::vector<LogicalLine> lexScript(std::string_view text, LexBudget* budget = nullptr);

// The closing bracket of '<', '{' or '['; 0 for anything else.
char closingBracket(char open);

}  // namespace glimmer
