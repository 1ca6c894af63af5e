// Where a shader declares a uniform: the line a student should look at when
// Glimmer says the uniform is read but never set. A text search (no
// compiler): the first line, outside comments, holding the word `uniform`
// and then the name as a whole word before the `;` that ends it.
#pragma once
#include <string>

namespace glimmer {

// The 1-based line of `name`'s uniform declaration in `text`, or 0.
int uniformDeclarationLine(const std::string& text, const std::string& name);

}  // namespace glimmer
