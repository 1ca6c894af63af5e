#include "lang/decimal_comma.h"
#include "util/numbers.h"


namespace glimmer {
namespace {

bool allDigits(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    return true;
}

// The character at (line, col) of the logical line's text; 0 when unknown.
char charAt(const LogicalLine& line, int lineNo, int col) {
    for (const Segment& seg : line.segments) {
        if (seg.line != lineNo) continue;
        int i = col - seg.col;
        if (i >= 0 && size_t(i) < seg.text.size()) return seg.text[size_t(i)];
    }
    return 0;
}

// `b` follows `a` with one comma between them and no blank.
bool commaGlued(const LogicalLine& line, const Token& a, const Token& b) {
    int after = a.loc.col + int(a.text.size());
    return a.loc.line == b.loc.line && b.loc.col == after + 1 && charAt(line, a.loc.line, after) == ',';
}

// "0" "01" -> a decimal-comma pair: an integer part (a sign allowed) and digits.
bool decimalPair(const Token& a, const Token& b) {
    if (a.kind != Token::Kind::Number || b.kind != Token::Kind::Number) return false;
    if (a.issue != Token::NumberIssue::None || b.issue != Token::NumberIssue::None) return false;
    std::string_view whole = a.text;
    if (!whole.empty() && (whole[0] == '-' || whole[0] == '+')) whole.remove_prefix(1);
    return allDigits(whole) && allDigits(b.text);
}

bool fits(char open, size_t n) {
    if (open == '<') return n == 1 || n == 3;  // a checkbox or a slider
    if (open == '{') return n == 3 || n == 4;  // a colour
    return n >= 2 && n <= 4;                   // a point or a vector
}

// Tokens [first, last) are the items of one group opened by `open`.
void group(LogicalLine& line, size_t first, size_t last, char open, std::vector<Token>& out) {
    std::vector<std::pair<size_t, size_t>> chunks;  // [begin, end) of tokens glued by commas
    for (size_t i = first; i < last; ++i) {
        if (i > first && commaGlued(line, line.tokens[i - 1], line.tokens[i])) chunks.back().second = i + 1;
        else chunks.push_back({i, i + 1});
    }
    bool pairs = false, decimal = chunks.size() >= 2;
    for (auto [b, e] : chunks) {
        if (e - b == 2 && decimalPair(line.tokens[b], line.tokens[b + 1])) pairs = true;
        else if (e - b != 1) decimal = false;
    }
    if (!decimal || !pairs || fits(open, last - first) || !fits(open, chunks.size())) {
        for (size_t i = first; i < last; ++i) out.push_back(std::move(line.tokens[i]));
        return;
    }
    for (auto [b, e] : chunks) {
        if (e - b == 1) {
            out.push_back(std::move(line.tokens[b]));
            continue;
        }
        Token t = line.tokens[b];
        const Token& frac = line.tokens[b + 1];
        std::string dotted = t.text + "." + frac.text;
        size_t skip = dotted[0] == '+' ? 1 : 0;
        parseDouble(dotted.data() + skip, dotted.data() + dotted.size(), t.number);
        t.text += "," + frac.text;
        t.issue = Token::NumberIssue::DecimalComma;
        out.push_back(std::move(t));
    }
}

}  // namespace

void readDecimalCommas(LogicalLine& line) {
    std::vector<Token> out;
    size_t i = 0, n = line.tokens.size();
    while (i < n) {
        if (line.tokens[i].kind != Token::Kind::Open) {
            out.push_back(std::move(line.tokens[i++]));
            continue;
        }
        size_t j = i + 1;
        while (j < n && line.tokens[j].kind != Token::Kind::Open && line.tokens[j].kind != Token::Kind::Close) ++j;
        if (j == n || line.tokens[j].kind != Token::Kind::Close) {  // not a plain group: the parser reports it
            out.push_back(std::move(line.tokens[i++]));
            continue;
        }
        char open = line.tokens[i].text[0];
        out.push_back(std::move(line.tokens[i]));
        group(line, i + 1, j, open, out);
        out.push_back(std::move(line.tokens[j]));
        i = j + 1;
    }
    line.tokens = std::move(out);
}

}  // namespace glimmer
