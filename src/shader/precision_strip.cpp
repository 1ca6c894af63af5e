#include "shader/precision_strip.h"

#include <vector>

#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"

namespace glimmer {

// A pass over the lexer's code tokens: comments and preprocessor lines are
// not among them, and a word is whole (`highpass`, `lowp2` are other words).
PrecisionStripResult stripPrecisionQualifiers(std::string_view source) {
    PrecisionStripResult r;
    if (glslVersionOf(source).number >= 130) {
        r.text.assign(source);
        return r;
    }
    const std::vector<GlslToken> t = glslCodeTokens(source);
    std::vector<GlslEdit> blanks;
    // Tokens [from, to) become spaces (their newlines stay).
    auto blank = [&](size_t from, size_t to) {
        const size_t begin = t[from].begin, end = to < t.size() ? t[to - 1].end : source.size();
        blanks.push_back(blankingEdit(source, begin, end));
        if (!r.firstLine) r.firstLine = t[from].line;
    };
    for (size_t k = 0; k < t.size(); ++k) {
        if (t[k].kind != GlslTokenKind::Word) continue;
        const std::string_view word = tokenText(source, t[k]);
        if (word == "precision") {  // `precision highp float;`, through its ';' (the text's end when none)
            size_t end = k;
            while (end < t.size() && !isPunctToken(source, t, end, ";")) ++end;
            blank(k, end + 1);
            k = end;
        } else if (word == "highp" || word == "mediump" || word == "lowp") {
            blank(k, k + 1);
        }
    }
    r.text = applyGlslEdits(source, std::move(blanks));
    return r;
}

}  // namespace glimmer
