#include "lang/lexer.h"

#include "lang/decimal_comma.h"
#include "lang/script.h"

#include <cmath>
#include <system_error>

#include "util/numbers.h"

namespace glimmer {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool isBracket(char c) {
    return c == '<' || c == '>' || c == '{' || c == '}' || c == '[' || c == ']';
}

bool isDelimiter(char c) { return isSpace(c) || isBracket(c) || c == ','; }

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool startsLikeNumber(std::string_view s) {
    if (s.empty()) return false;
    if (isDigit(s[0]) || s[0] == '.') return true;
    return (s[0] == '-' || s[0] == '+') && s.size() > 1 && (isDigit(s[1]) || s[1] == '.');
}

// Where a comment starts in a physical line, or npos.
size_t commentStart(std::string_view line) {
    size_t hash = line.find('#');
    size_t slashes = line.find("//");
    return std::min(hash, slashes);
}

// Classifies a raw token. A number-like token whose tail after the longest
// valid prefix holds anything but digits, dots and signs is a Word: that keeps
// file names such as "2d.bmp" or "1.obj" intact while "4.8." and "1.." are
// still read the way glman's strtod read them.
Token makeToken(std::string_view raw, SourceLoc loc) {
    Token t;
    t.text = std::string(raw);
    t.loc = loc;
    t.kind = Token::Kind::Word;
    if (!startsLikeNumber(raw)) return t;

    // Locale-independent (strtod is not), but like from_chars it rejects a leading '+'.
    size_t skip = raw[0] == '+' ? 1 : 0;
    double value = 0;
    auto [ptr, ec] = parseDouble(raw.data() + skip, raw.data() + raw.size(), value);
    size_t used = static_cast<size_t>(ptr - raw.data());
    if (ec == std::errc::invalid_argument || used == skip) return t;
    std::string_view tail = raw.substr(used);
    for (char c : tail) {
        if (!isDigit(c) && c != '.' && c != '-' && c != '+') return t;
    }
    t.kind = Token::Kind::Number;
    t.number = value;
    if (ec == std::errc::result_out_of_range) {
        t.number = 0;
        t.issue = Token::NumberIssue::OutOfRange;
    } else if (!tail.empty()) {
        t.issue = Token::NumberIssue::Malformed;
    }
    return t;
}

// False when the budget is spent: the token at `loc` is not kept.
bool charge(LexBudget* budget, size_t textBytes, SourceLoc loc) {
    if (!budget || budget->maxBytes == 0) return true;
    budget->used += tokenCharge(textBytes);
    if (budget->used <= budget->maxBytes) return true;
    budget->overAt = loc;
    return false;
}

void tokenize(const Segment& seg, std::vector<Token>& out, LexBudget* budget) {
    const std::string& s = seg.text;
    size_t i = 0;
    while (i < s.size() && !(budget && budget->over())) {
        char c = s[i];
        if (isSpace(c) || c == ',') {
            ++i;
            continue;
        }
        SourceLoc loc{seg.line, seg.col + static_cast<int>(i)};
        size_t j = i + 1;
        if (!isBracket(c))
            while (j < s.size() && !isDelimiter(s[j])) ++j;
        if (!charge(budget, j - i, loc)) return;
        if (isBracket(c)) {
            Token t;
            bool open = c == '<' || c == '{' || c == '[';
            t.kind = open ? Token::Kind::Open : Token::Kind::Close;
            t.text = std::string(1, c);
            t.loc = loc;
            out.push_back(std::move(t));
            ++i;
            continue;
        }
        out.push_back(makeToken(std::string_view(s).substr(i, j - i), loc));
        i = j;
    }
}

}  // namespace

char closingBracket(char open) {
    switch (open) {
        case '<': return '>';
        case '{': return '}';
        case '[': return ']';
        default: return 0;
    }
}

std::uint64_t tokenCharge(size_t textBytes) {
    // The token and the parser's Arg, each twice for a vector's growth, and
    // the characters in both.
    return 2 * (sizeof(Token) + sizeof(Arg)) + 2 * std::uint64_t(textBytes);
}

std::vector<LogicalLine> lexScript(std::string_view text, LexBudget* budget) {
    std::vector<LogicalLine> lines;
    LogicalLine current;
    auto flush = [&] {
        readDecimalCommas(current);  // `< 0,01 0.1 1.0 >`
        if (!current.tokens.empty()) lines.push_back(std::move(current));
        current = LogicalLine{};
    };

    size_t pos = 0;
    int lineNo = 0;
    while (pos < text.size() && !(budget && budget->over())) {
        ++lineNo;
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;

        // A `\` inside a comment does not continue the line, so the comment goes first.
        line = line.substr(0, std::min(line.size(), commentStart(line)));
        while (!line.empty() && isSpace(line.back())) line.remove_suffix(1);
        bool continues = !line.empty() && line.back() == '\\';
        if (continues) line.remove_suffix(1);

        int col = 1;
        // Some editors put a UTF-8 byte-order mark first; columns stay byte columns.
        if (lineNo == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") {
            line.remove_prefix(3);
            col = 4;
        }
        Segment seg{lineNo, col, std::string(line)};
        tokenize(seg, current.tokens, budget);
        current.segments.push_back(std::move(seg));
        if (!continues) flush();
    }
    flush();
    return lines;
}

}  // namespace glimmer
