// What a shader's text says about the pixels a draw covers, for skipping a
// Clear that a later draw paints over (plan/hidden_clears.h). Both answers
// err on the side of "no": a shader they cannot vouch for keeps its Clear.
#pragma once
#include <string>

namespace glimmer {

// The vertex shader places vertices exactly where the fixed-function
// transform would: its only write of gl_Position is
// `gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;` (spaces and
// comments aside) or `= ftransform();`, and no directive names gl_Position.
bool keepsPlainTransform(const std::string& vertexText);

// The fragment shader may leave pixels unwritten: the word `discard`
// appears in its code or in a directive (`#define KILL discard`); one in a
// comment is not code (and a false "maybe" would cost only the Clear).
bool mayDiscard(const std::string& fragmentText);

}  // namespace glimmer
