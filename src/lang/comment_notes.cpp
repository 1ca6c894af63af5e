#include "lang/comment_notes.h"

#include <vector>

namespace glimmer {

std::string commentNoteAbove(std::string_view text, int line) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start <= text.size() && int(lines.size()) < line - 1) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view l = text.substr(start, end - start);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        lines.push_back(l);
        start = end + 1;
    }
    if (int(lines.size()) < line - 1) return {};
    std::vector<std::string_view> block;
    for (int i = line - 2; i >= 0; --i) {
        std::string_view l = lines[size_t(i)];
        size_t b = l.find_first_not_of(" \t");
        if (b == std::string_view::npos || l.compare(b, 2, "##") != 0) break;
        l.remove_prefix(b + 2);
        if (!l.empty() && (l.front() == ' ' || l.front() == '\t')) l.remove_prefix(1);
        if (l.rfind("OpenGL GLIB", 0) == 0) break;  // glman's header line, not a note
        block.push_back(l);
    }
    std::string out;
    for (auto it = block.rbegin(); it != block.rend(); ++it) out += (out.empty() ? "" : "\n") + std::string(*it);
    return out;
}

}  // namespace glimmer
