// Diagnostics are values: every layer appends to a Diagnostics list and the
// front end decides how to print them. Nothing below the front end exits.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace glimmer {

struct SourceLoc {
    int line = 0;  // 1-based; 0 means "no particular line"
    int col = 0;   // 1-based column of the first character
};

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;  // as the user named it (script path, shader path, ...)
    SourceLoc loc;
    std::string message;
};

class Diagnostics {
public:
    void error(const std::string& file, SourceLoc loc, std::string message);
    void warning(const std::string& file, SourceLoc loc, std::string message);
    void note(const std::string& file, SourceLoc loc, std::string message);
    void add(Diagnostic d) { list_.push_back(std::move(d)); }

    bool hasErrors() const;
    int errorCount() const;
    int warningCount() const;
    const std::vector<Diagnostic>& all() const { return list_; }
    void clear() { list_.clear(); }

private:
    std::vector<Diagnostic> list_;
};

// The text of every file a diagnostic may point into, so the printer can show
// the offending line under the message.
class SourceTexts {
public:
    void add(const std::string& file, std::string text) { texts_[file] = std::move(text); }
    // The 1-based line of `file`, without its line ending; empty if unknown.
    std::string line(const std::string& file, int line) const;

private:
    std::map<std::string, std::string> texts_;
};

// clang style: "file:line:col: error: message", then the source line and a
// caret under the column (omitted when the line is unknown).
// Lines are joined with '\n'; there is no newline after the last one.
std::string formatDiagnostic(const Diagnostic& d, const SourceTexts& sources);

const char* severityName(Severity s);

}  // namespace glimmer
