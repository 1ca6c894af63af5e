#include "shader/gs4_translate.h"
#include "shader/glsl_scan.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>

namespace glimmer {
namespace {

struct Token {
    enum class Kind { Ident, Number, Punct, Directive };
    Kind kind;
    size_t begin, end;  // byte offsets into the source
    std::string_view text;
};


// Enough of GLSL to find identifiers and brackets: comments, strings and
// whitespace are skipped; a preprocessor line is one Directive token.
std::vector<Token> tokenize(std::string_view s) {
    std::vector<Token> out;
    size_t i = 0, n = s.size();
    bool lineStart = true;  // only blanks since the last newline
    while (i < n) {
        char c = s[i];
        if (c == '\n') {
            lineStart = true;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (size_t e = commentEnd(s, i); e != i) {
            i = e;
            continue;  // a block comment does not end the line
        }
        if (c == '#' && lineStart) {
            size_t b = i;
            while (i < n && s[i] != '\n') {
                if (s[i] == '\\' && i + 1 < n && s[i + 1] == '\n') ++i;  // continued
                else if (s[i] == '\\' && i + 2 < n && s[i + 1] == '\r' && s[i + 2] == '\n') i += 2;
                ++i;
            }
            size_t e = i;
            while (e > b && (s[e - 1] == '\r')) --e;
            out.push_back({Token::Kind::Directive, b, e, s.substr(b, e - b)});
            continue;
        }
        lineStart = false;
        if (c == '"') {  // not GLSL, but seen in #error text and in macros; skip it whole
            size_t b = i++;
            while (i < n && s[i] != '"' && s[i] != '\n') i += s[i] == '\\' ? 2 : 1;
            if (i < n && s[i] == '"') ++i;
            out.push_back({Token::Kind::Punct, b, std::min(i, n), s.substr(b, std::min(i, n) - b)});
            continue;
        }
        size_t b = i;
        if (isGlslWordStart(c)) {
            while (i < n && isGlslWordChar(s[i])) ++i;
            out.push_back({Token::Kind::Ident, b, i, s.substr(b, i - b)});
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            while (i < n && (isGlslWordChar(s[i]) || s[i] == '.')) ++i;
            out.push_back({Token::Kind::Number, b, i, s.substr(b, i - b)});
        } else {
            ++i;
            out.push_back({Token::Kind::Punct, b, i, s.substr(b, 1)});
        }
    }
    return out;
}

struct Edit {
    size_t at, erase;
    std::string insert;
};

// EXT per-vertex input arrays and the gl_in member each becomes.
const std::map<std::string_view, std::string_view>& inputArrays() {
    static const std::map<std::string_view, std::string_view> m = {
        {"gl_PositionIn", "gl_Position"},
        {"gl_PointSizeIn", "gl_PointSize"},
        {"gl_ClipVertexIn", "gl_ClipVertex"},
        {"gl_FrontColorIn", "gl_FrontColor"},
        {"gl_BackColorIn", "gl_BackColor"},
        {"gl_FrontSecondaryColorIn", "gl_FrontSecondaryColor"},
        {"gl_BackSecondaryColorIn", "gl_BackSecondaryColor"},
        {"gl_TexCoordIn", "gl_TexCoord"},
        {"gl_FogFragCoordIn", "gl_FogFragCoord"},
    };
    return m;
}

bool isPrimitiveWord(std::string_view w) {
    return w == "points" || w == "lines" || w == "lines_adjacency" || w == "triangles" ||
           w == "triangles_adjacency";
}

int lineOf(std::string_view s, size_t offset) {
    return 1 + int(std::count(s.begin(), s.begin() + std::ptrdiff_t(std::min(offset, s.size())), '\n'));
}

// "#  extension   GL_EXT_geometry_shader4 : enable" -> true
bool isGs4Extension(std::string_view d) {
    size_t p = d.find_first_not_of(" \t", 1);
    if (p == std::string_view::npos || d.compare(p, 9, "extension") != 0) return false;
    p = d.find_first_not_of(" \t", p + 9);
    return p != std::string_view::npos && d.compare(p, 23, "GL_EXT_geometry_shader4") == 0 &&
           (p + 23 == d.size() || !isGlslWordChar(d[p + 23]));
}

// "#version 120" -> 120; 0 when not a #version line.
int versionNumber(std::string_view d) {
    size_t p = d.find_first_not_of(" \t", 1);
    if (p == std::string_view::npos || d.compare(p, 7, "version") != 0) return 0;
    p = d.find_first_not_of(" \t", p + 7);
    if (p == std::string_view::npos) return 0;
    int v = 0;
    std::from_chars(d.data() + p, d.data() + d.size(), v);
    return v;
}

}  // namespace

Gs4Result translateGs4(std::string_view src, const Gs4Options& options) {
    Gs4Result r;
    std::vector<Token> toks = tokenize(src);
    std::vector<Edit> edits;
    auto note = [&](std::string what, size_t offset) {
        r.usesExt = true;
        if (!r.firstExtLine) r.firstExtLine = lineOf(src, offset);
        if (std::find(r.rewrites.begin(), r.rewrites.end(), what) == r.rewrites.end()) r.rewrites.push_back(std::move(what));
    };
    auto ident = [&](size_t k, std::string_view w) {
        return k < toks.size() && toks[k].kind == Token::Kind::Ident && toks[k].text == w;
    };
    auto punct = [&](size_t k, char c) {
        return k < toks.size() && toks[k].kind == Token::Kind::Punct && toks[k].text.size() == 1 && toks[k].text[0] == c;
    };

    const Token* version = nullptr;
    size_t firstCode = toks.size();  // the first token that is not a directive
    int depth = 0;                   // braces
    for (size_t k = 0; k < toks.size(); ++k) {
        const Token& t = toks[k];
        if (t.kind == Token::Kind::Directive) {
            if (!version && versionNumber(t.text)) version = &t;
            if (isGs4Extension(t.text)) {
                // Keep the line (and any continued lines) so line numbers stay.
                edits.push_back({t.begin, t.end - t.begin,
                                 std::string(size_t(std::count(t.text.begin(), t.text.end(), '\n')), '\n')});
                note("#extension GL_EXT_geometry_shader4 dropped", t.begin);
            }
            continue;
        }
        if (firstCode == toks.size()) firstCode = k;
        if (punct(k, '{')) ++depth;
        if (punct(k, '}')) depth = std::max(0, depth - 1);
        if (t.kind != Token::Kind::Ident) continue;

        if (auto it = inputArrays().find(t.text); it != inputArrays().end() && punct(k + 1, '[')) {
            size_t close = k + 1;
            for (int nest = 0; close < toks.size(); ++close) {
                if (punct(close, '[')) ++nest;
                if (punct(close, ']') && --nest == 0) break;
            }
            if (close == toks.size()) continue;  // unbalanced: the compiler will say so
            edits.push_back({t.begin, t.text.size(), "gl_in"});
            edits.push_back({toks[close].end, 0, "." + std::string(it->second)});
            std::string member(it->second);
            note(std::string(t.text) + (t.text == "gl_TexCoordIn" ? "[i][j] -> gl_in[i]." + member + "[j]"
                                                                    : "[i] -> gl_in[i]." + member),
                 t.begin);
        } else if (t.text == "gl_VerticesIn") {
            if (depth == 0 && k > 0 && punct(k - 1, '[') && punct(k + 1, ']')) {
                edits.push_back({t.begin, t.text.size(), ""});  // an input array's size: unsized
                note("[gl_VerticesIn] -> []", t.begin);
            } else {
                edits.push_back({t.begin, t.text.size(), "gl_in.length()"});
                note("gl_VerticesIn -> gl_in.length()", t.begin);
            }
        } else if (t.text == "varying") {
            if (ident(k + 1, "in") || ident(k + 1, "out")) {
                bool blank = t.end < src.size() && (src[t.end] == ' ' || src[t.end] == '\t');
                edits.push_back({t.begin, t.text.size() + (blank ? 1 : 0), ""});
                note(std::string("varying ") + std::string(toks[k + 1].text) + " -> " + std::string(toks[k + 1].text),
                     t.begin);
            } else if (depth == 0) {
                edits.push_back({t.begin, t.text.size(), "out"});
                note("varying -> out", t.begin);
            }
        } else if (t.text == "layout" && punct(k + 1, '(')) {
            size_t j = k + 2;
            bool primitive = false;
            for (; j < toks.size() && !punct(j, ')'); ++j) primitive |= toks[j].kind == Token::Kind::Ident && isPrimitiveWord(toks[j].text);
            if (primitive && ident(j + 1, "in")) r.hasInputLayout = true;
        }
    }

    if (!r.hasInputLayout && !options.inputPrimitive.empty() && firstCode < toks.size()) {
        edits.push_back({toks[firstCode].begin, 0, "layout(" + options.inputPrimitive + ") in; "});
        r.addedInputLayout = true;
    }
    if (r.usesExt && version && versionNumber(version->text) < 150) {
        edits.push_back({version->begin, version->end - version->begin, "#version 150 compatibility"});
        r.rewrites.push_back("#version " + std::to_string(versionNumber(version->text)) + " -> #version 150 compatibility");
    }

    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.at < b.at; });
    size_t pos = 0;
    for (const Edit& e : edits) {
        if (e.at < pos) continue;  // overlapping: cannot happen with the rules above
        r.text.append(src.substr(pos, e.at - pos));
        r.text += e.insert;
        pos = e.at + e.erase;
    }
    r.text.append(src.substr(std::min(pos, src.size())));
    return r;
}

}  // namespace glimmer
