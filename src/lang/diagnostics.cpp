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

bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

std::string sanitizeForTerminal(const std::string& text, bool keepNewlines) {
    std::string out;
    size_t chars = 0;  // on the current line
    bool cut = false;
    for (char ch : text) {
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
        if (isControl(c) && !(c == '\t')) out += escaped(c);
        else out += ch;
    }
    return out;
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
    std::string out = d.file;
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
        const std::string piece = isControl(static_cast<unsigned char>(c)) && c != '\t' ? escaped(c) : std::string(1, c);
        shown += piece;
        // Columns count bytes, but the caret must line up on screen: copy
        // tabs, and give a multi-byte UTF-8 character one space.
        if (i < col && !continuation(c)) pad += c == '\t' ? std::string("\t") : std::string(piece.size(), ' ');
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
