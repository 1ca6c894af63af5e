// A watch: the value of one GLSL expression, as it stands right after the
// statement on one line of a shader runs, captured for every pixel of the
// pass (issue 28). This file rewrites a stage's text so that it does so; it
// knows nothing of OpenGL, and never touches the user's file.
//
// Contract:
//   - The capture goes on the watched line itself and the helpers on the
//     line of the first function, so every line keeps its number: the
//     driver's messages about the rewritten text point at the user's lines.
//   - The rewritten fragment stage writes exactly two outputs: the value
//     (kWatchValueOut, location 0: the expression widened to a vec4) and
//     what is known of it (kWatchInfoOut, location 1: x = 1 where the
//     fragment ran, y = its component count / 4, 0 where the line did not
//     run there, z = its kind / 3, WatchKind: fractions, so an 8-bit target
//     holds them, a quarter of the bytes a float one takes, which on a GPU
//     is the watch's cost; gl/watch_gpu.cpp). The shader's own outputs become plain
//     globals, so its main runs unchanged and discards still discard.
//   - The expression's type is found by the compiler (overloads of
//     kWatchStore), not here: a matrix or a struct fails to compile on the
//     watched line, and pipeline/watch.cpp says what can be watched.
//   - Bounded: one pass over the text per step, no recursion, no regex; an
//     expression is at most kMaxWatchExpression characters.
#pragma once
#include <string>
#include <string_view>

namespace glimmer {

constexpr std::string_view kWatchValueOut = "glimmer_watch_value";
constexpr std::string_view kWatchInfoOut = "glimmer_watch_info";
constexpr std::string_view kWatchStore = "glimmer_watch_store";
constexpr size_t kMaxWatchExpression = 200;

// What kind of value a watch holds (the info output's z).
enum class WatchKind { Float = 0, Int = 1, Uint = 2, Bool = 3 };

// FILE:LINE:EXPR (render --watch) or FILE:LINE EXPR (the viewer's field).
struct WatchSpec {
    std::string file;
    int line = 0;
    std::string expression;
};
// False and why when `text` is neither form, the line is not a positive
// number or the expression is not one expression (watchExpressionProblem).
bool parseWatchSpec(std::string_view text, WatchSpec& out, std::string& why);

// Why `expression` cannot be put into a shader as one expression (empty,
// too long, a ';', '{', '}', '#', a comment, a line break, unbalanced
// brackets); "" when it can.
std::string watchExpressionProblem(std::string_view expression);

// The rewritten text, or why not and where (1-based column on the watched
// line; 0 when the whole line is meant).
struct WatchedStage {
    bool ok = false;
    std::string text;
    std::string error;
    int column = 0;
};

// The fragment stage with `expression` watched at `line`.
WatchedStage watchFragment(std::string_view source, int line, std::string_view expression);
// A vertex watch: the vertex stage captures into an added output, and the
// program's fragment stage (watchFragmentOfVertex) writes what reaches it,
// interpolated across the primitive.
WatchedStage watchVertex(std::string_view source, int line, std::string_view expression);
WatchedStage watchFragmentOfVertex(std::string_view fragmentSource);

}  // namespace glimmer
