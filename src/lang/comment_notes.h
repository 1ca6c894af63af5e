// A script's own words about a pass: the `##` comment block written right
// above a line (teachers annotate each Program this way), for the viewer to
// show beside that Program's controls. No OpenGL here.
#pragma once
#include <string>
#include <string_view>

namespace glimmer {

// The lines starting with "##" directly above `line` (1-based) in `text`,
// without the marks and the blank after them, joined by newlines. glman's
// "##OpenGL GLIB" header is not a note. Empty when there is no such block.
std::string commentNoteAbove(std::string_view text, int line);

}  // namespace glimmer
