// The small pieces of GLSL reading every shader rewrite and check needs,
// written once: what a word character is, the #version directive, lines,
// and NVIDIA's const leniency. What reads GLSL goes through the one lexer
// (shader/glsl_lexer.h), never a walk of its own over characters and never
// a regular expression: std::regex recurses per character and overflowed
// the stack on a 30,000-character line (issue 30), and a student's shader is
// untrusted.
//
// Contract:
//   - Nothing here recurses or throws; every input, however long or odd,
//     gets an answer in time linear in its size.
//   - Numbers are saturated, never converted with std::stoi (which throws on
//     "#version 99999999999999999999").
#pragma once
#include <string>
#include <string_view>

namespace glimmer {

// A letter, digit or underscore: the characters of a GLSL identifier.
inline bool isGlslWordChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// A letter or underscore: what may start a GLSL identifier.
inline bool isGlslWordStart(char c) { return isGlslWordChar(c) && !(c >= '0' && c <= '9'); }

// The shader's #version directive: its number (110 when none; saturated at
// kMaxGlslVersionNumber), its profile word ("" when none) and its 1-based line
// (0 when none). Only the first directive counts, as for the compiler; one in
// a comment does not. `wellFormed` is false when the number is not all
// digits or something other than blanks or comments follows the profile.
// `numberEnd`: the offset in `source` just past the number (npos when none),
// where a profile word may be put (gl/shader_build.cpp adds "compatibility").
constexpr int kMaxGlslVersionNumber = 999999;
struct GlslVersion {
    int number = 110;
    std::string profile;
    int line = 0;
    bool wellFormed = true;
    size_t numberEnd = std::string_view::npos;
};
GlslVersion glslVersionOf(std::string_view source);

// Where line `line` (1-based) of `text` starts; npos when the text has fewer
// lines. lineOf: that line without its '\n' ("" when there is none).
size_t lineStartOf(std::string_view text, int line);
std::string_view lineOf(std::string_view text, int line);

// `text` with the last whole word 'const' before column `col` of line
// `line` blanked out (columns keep their places); unchanged when there is
// none. NVIDIA's leniency for a global const set from a uniform, on the
// desktop (gl/shader_build.cpp) and in the page (shader/web_translate.cpp).
std::string withoutConstBefore(std::string text, int line, int col);
// What both say when they drop it; `quoted`: the name as "`k2'".
std::string globalConstDropped(const std::string& quoted);

// The first whole word of `text` that starts with `prefix` ("gl_" finds
// "gl_Vertex" in "'gl_Vertex' : undeclared identifier"); "" when none.
// It reads a compiler's log message, not GLSL, so not through the lexer.
std::string firstWordWithPrefix(std::string_view text, std::string_view prefix);

}  // namespace glimmer
