#include "lang/diagnostics.h"

#include <algorithm>

namespace glimmer {

void Diagnostics::error(const std::string& file, SourceLoc loc, std::string message) {
    add({Severity::Error, file, loc, std::move(message), false});
}

void Diagnostics::warning(const std::string& file, SourceLoc loc, std::string message) {
    add({Severity::Warning, file, loc, std::move(message), false});
}

void Diagnostics::note(const std::string& file, SourceLoc loc, std::string message) {
    add({Severity::Note, file, loc, std::move(message), false});
}

void Diagnostics::add(Diagnostic d) {
    errors_ += d.severity == Severity::Error;
    warnings_ += d.severity == Severity::Warning;
    list_.push_back(std::move(d));
}

bool Diagnostics::hasErrors() const { return errors_ > 0; }

int Diagnostics::errorCount() const { return errors_; }

int Diagnostics::warningCount() const { return warnings_; }

void SourceTexts::add(const std::string& file, std::string text) {
    Text t;
    t.starts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') t.starts.push_back(i + 1);
    t.text = std::move(text);
    texts_[file] = std::move(t);
}

std::string SourceTexts::line(const std::string& file, int line) const {
    auto it = texts_.find(file);
    if (it == texts_.end() || line < 1) return {};
    const Text& t = it->second;
    if (size_t(line) > t.starts.size()) return {};
    const size_t start = t.starts[size_t(line) - 1];
    size_t end = size_t(line) < t.starts.size() ? t.starts[size_t(line)] - 1 : t.text.size();
    if (end > start && t.text[end - 1] == '\r') --end;
    return t.text.substr(start, end - start);
}

namespace {

bool isControl(unsigned char c) { return c < 0x20 || c == 0x7f; }

std::string escaped(unsigned char c) {
    static const char* hex = "0123456789abcdef";
    return std::string("\\x") + hex[c >> 4] + hex[c & 15];
}

// How many bytes of a control character start at `i` (tab excepted): 1 for
// C0 and DEL, 2 for a C1 character in UTF-8 (U+0080..U+009F, "\xc2\x9b" is
// CSI: a terminal takes it as the start of an escape sequence), 1 for a byte
// above 0x7f that is no part of a whole UTF-8 character (a lone 0x9b is CSI
// to a terminal in an 8-bit mode; issue 37); 0 for text.
size_t controlBytes(const std::string& s, size_t i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (isControl(c)) return c == '\t' ? 0 : 1;
    if (c < 0x80) return 0;
    if (const size_t n = utf8Length(s, i)) {
        const unsigned char d = static_cast<unsigned char>(s[i + 1]);
        return c == 0xc2 && d >= 0x80 && d <= 0x9f ? 2 : 0;
    }
    if ((c & 0xC0) == 0x80)  // a continuation byte: text when a whole character before it covers it
        for (size_t back = 1; back <= 3 && back <= i; ++back)
            if (utf8Length(s, i - back) > back) return 0;
    return 1;
}

// The control character at `i` (controlBytes(s, i) bytes) as \xNN escapes.
std::string escapedAt(const std::string& s, size_t i, size_t n) {
    std::string out;
    for (size_t k = 0; k < n; ++k) out += escaped(static_cast<unsigned char>(s[i + k]));
    return out;
}

bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

size_t utf8Length(const std::string& s, size_t j) {
    const unsigned char c = static_cast<unsigned char>(s[j]);
    const size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (n == 0 || j + n > s.size()) return 0;
    for (size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(s[j + k]) & 0xC0) != 0x80) return 0;
    return n;
}

std::string sanitizeForTerminal(const std::string& text, bool keepNewlines) {
    std::string out;
    size_t chars = 0;  // on the current line
    bool cut = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        const unsigned char c = static_cast<unsigned char>(ch);
        if (keepNewlines && c == '\n') {
            out += '\n';
            chars = 0;
            cut = false;
            continue;
        }
        if (cut) continue;
        if (!continuation(ch) && chars == kMaxEchoedChars) {
            out += "...";
            cut = true;
            continue;
        }
        if (!continuation(ch)) ++chars;
        if (size_t n = controlBytes(text, i)) {
            out += escapedAt(text, i, n);
            i += n - 1;
        } else {
            out += ch;
        }
    }
    return out;
}

std::string overMemoryBudget(std::uint64_t neededBytes, std::uint64_t budgetBytes) {
    auto mib = [](std::uint64_t b) { return (b + (std::uint64_t(1) << 20) - 1) >> 20; };
    return "the script's textures, targets, meshes and parsed lines need " + std::to_string(mib(neededBytes)) +
           " MiB by this line, more than the memory budget of " + std::to_string(budgetBytes >> 20) +
           " MiB (--max-memory)";
}

const char* severityName(Severity s) {
    switch (s) {
        case Severity::Note: return "note";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "error";
}

std::string formatDiagnostic(const Diagnostic& d, const SourceTexts& sources) {
    std::string out = sanitizeForTerminal(d.file, false);  // a folder name may hold ESC (issue 37)
    if (d.loc.line > 0) {
        out += ':' + std::to_string(d.loc.line);
        if (d.loc.col > 0) out += ':' + std::to_string(d.loc.col);
    }
    if (!out.empty()) out += ": ";
    out += severityName(d.severity);
    out += ": ";
    out += sanitizeForTerminal(d.message, true);
    // The OpenGL driver's own words, not Glimmer's: said so, as compilers tag
    // a warning with the flag that raised it.
    if (d.fromDriver) out += " [driver]";
    if (d.loc.line <= 0) return out;

    const std::string src = sources.line(d.file, d.loc.line);
    if (src.empty()) return out;
    // A window of at most kMaxEchoedChars characters around the column,
    // control characters escaped; the caret is placed on what is shown.
    const size_t col = d.loc.col > 0 ? size_t(d.loc.col - 1) : 0;
    size_t first = 0;
    size_t total = 0;
    for (char c : src) total += !continuation(c);
    std::string shown, pad;
    if (total > kMaxEchoedChars) {
        first = col > kMaxEchoedChars / 2 ? std::min(col - kMaxEchoedChars / 2, src.size()) : 0;
        while (first < src.size() && continuation(src[first])) ++first;
        if (first > 0) {
            shown = "...";
            pad = "   ";
        }
    }
    size_t chars = 0, i = first;
    for (; i < src.size(); ++i) {
        const char c = src[i];
        if (!continuation(c) && chars == kMaxEchoedChars) {
            shown += "...";
            break;
        }
        if (!continuation(c)) ++chars;
        const size_t n = controlBytes(src, i);
        const std::string piece = n ? escapedAt(src, i, n) : std::string(1, c);
        shown += piece;
        // Columns count bytes, but the caret must line up on screen: copy
        // tabs, and give a multi-byte UTF-8 character one space.
        if (i < col && !continuation(c)) pad += c == '\t' ? std::string("\t") : std::string(piece.size(), ' ');
        if (n > 1) i += n - 1;  // the C1 character's second byte is in `piece`
    }
    out += '\n';
    out += shown;
    if (d.loc.col <= 0) return out;
    out += '\n';
    if (col > src.size()) pad += std::string(col - src.size(), ' ');  // past the end of the line
    out += pad;
    out += '^';
    return out;
}

}  // namespace glimmer
