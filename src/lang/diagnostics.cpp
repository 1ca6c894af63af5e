#include "lang/diagnostics.h"

#include <algorithm>

namespace glimmer {

void Diagnostics::error(const std::string& file, SourceLoc loc, std::string message) {
    add({Severity::Error, file, loc, std::move(message)});
}

void Diagnostics::warning(const std::string& file, SourceLoc loc, std::string message) {
    add({Severity::Warning, file, loc, std::move(message)});
}

void Diagnostics::note(const std::string& file, SourceLoc loc, std::string message) {
    add({Severity::Note, file, loc, std::move(message)});
}

bool Diagnostics::hasErrors() const { return errorCount() > 0; }

int Diagnostics::errorCount() const {
    return static_cast<int>(std::count_if(list_.begin(), list_.end(),
                                          [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

int Diagnostics::warningCount() const {
    return static_cast<int>(std::count_if(list_.begin(), list_.end(),
                                          [](const Diagnostic& d) { return d.severity == Severity::Warning; }));
}

std::string SourceTexts::line(const std::string& file, int line) const {
    auto it = texts_.find(file);
    if (it == texts_.end() || line < 1) return {};
    const std::string& text = it->second;
    size_t start = 0;
    for (int n = 1; n < line; ++n) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) return {};
        start = nl + 1;
    }
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return text.substr(start, end - start);
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
    out += d.message;
    if (d.loc.line <= 0) return out;

    std::string src = sources.line(d.file, d.loc.line);
    if (src.empty()) return out;
    out += '\n';
    out += src;
    if (d.loc.col <= 0) return out;
    out += '\n';
    // Columns count bytes, but the caret must line up on screen: copy tabs, and
    // give a multi-byte UTF-8 character one space, not one per byte.
    size_t prefix = static_cast<size_t>(d.loc.col - 1);
    for (size_t i = 0; i < prefix; ++i) {
        char c = i < src.size() ? src[i] : ' ';
        bool continuation = (static_cast<unsigned char>(c) & 0xC0) == 0x80;
        if (continuation) continue;
        out += c == '\t' ? '\t' : ' ';
    }
    out += '^';
    return out;
}

}  // namespace glimmer
