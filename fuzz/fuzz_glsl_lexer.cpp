// libFuzzer: the one GLSL lexer (shader/glsl_lexer.h) on arbitrary bytes,
// its contract checked on every input: the tokens tile the text exactly,
// none is empty, and each one's line and column are those of its first
// byte (counted here the slow, obvious way).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "shader/glsl_lexer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glimmer;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::vector<GlslToken> tokens = lexGlsl(text);
    size_t at = 0;
    int line = 1, col = 1;
    for (const GlslToken& t : tokens) {
        if (t.begin != at || t.end <= t.begin || t.end > text.size()) __builtin_trap();  // tiles, never empty
        if (t.line != line || t.col != col) __builtin_trap();
        const std::string_view s = tokenText(text, t);
        // Only these kinds may hold a line break; a Newline is exactly one.
        const bool breaks = s.find('\n') != std::string_view::npos;
        if (breaks && t.kind != GlslTokenKind::Newline && t.kind != GlslTokenKind::BlockComment &&
            t.kind != GlslTokenKind::Directive)
            __builtin_trap();
        if (t.kind == GlslTokenKind::Newline && s != "\n" && s != "\r\n") __builtin_trap();
        if (t.kind == GlslTokenKind::Other && s.size() != 1) __builtin_trap();
        for (char c : s) {
            if (c == '\n') ++line, col = 1;
            else ++col;
        }
        at = t.end;
    }
    if (at != text.size()) __builtin_trap();
    // The helpers on the same tokens: brackets pair both ways.
    const std::vector<GlslToken> code = glslCodeTokens(text);
    const std::vector<size_t> mate = matchingBrackets(text, code);
    for (size_t k = 0; k < code.size(); ++k)
        if (mate[k] != std::string_view::npos && (mate[k] >= code.size() || mate[mate[k]] != k)) __builtin_trap();
    return 0;
}
