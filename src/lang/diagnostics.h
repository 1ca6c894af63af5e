// Diagnostics are values: every layer appends to a Diagnostics list and the
// front end decides how to print them. Nothing below the front end exits.
#pragma once
#include <cstdint>
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
    // A line of the OpenGL driver's compile or link log (gl/compiler_log):
    // its words are the driver's, and its later errors may only follow from
    // an earlier one (pipeline/error_cascades.h).
    bool fromDriver = false;
};

class Diagnostics {
public:
    void error(const std::string& file, SourceLoc loc, std::string message);
    void warning(const std::string& file, SourceLoc loc, std::string message);
    void note(const std::string& file, SourceLoc loc, std::string message);
    void add(Diagnostic d);

    bool hasErrors() const;
    int errorCount() const;
    int warningCount() const;
    const std::vector<Diagnostic>& all() const { return list_; }
    void clear() {
        list_.clear();
        errors_ = warnings_ = 0;
    }

private:
    std::vector<Diagnostic> list_;
    int errors_ = 0, warnings_ = 0;  // counted as they are added: asking is O(1)
};

// The text of every file a diagnostic may point into, so the printer can show
// the offending line under the message.
// Each text's line starts are indexed once, when it is added, so printing
// many diagnostics costs no more than printing one each.
class SourceTexts {
public:
    void add(const std::string& file, std::string text);
    // The 1-based line of `file`, without its line ending; empty if unknown.
    std::string line(const std::string& file, int line) const;

private:
    struct Text {
        std::string text;
        std::vector<size_t> starts;  // offset of each line's first byte
    };
    std::map<std::string, Text> texts_;
};

// What a diagnostic may echo of the user's text: at most this many
// characters of a source line (a window around the caret) and of each line
// of a message. Control characters other than tab are shown escaped (\x1b),
// so a script cannot send terminal escapes to a grader's console.
constexpr size_t kMaxEchoedChars = 200;
// How many diagnostics a front end prints before "N more not shown".
constexpr size_t kMaxPrintedDiagnostics = 100;

// `text` made safe to print: control characters escaped (newlines and tabs
// kept when `keepNewlines`), each line cut to kMaxEchoedChars characters.
std::string sanitizeForTerminal(const std::string& text, bool keepNewlines);

// The length in bytes of the whole UTF-8 character that starts at `j` of
// `s`, or 0 when no valid one does (a stray byte, a cut sequence).
std::size_t utf8Length(const std::string& s, std::size_t j);

// The one message for a script past --max-memory, whichever step counted it
// (the parser's structures, the plan's textures and targets, the load step's
// images, meshes and models): "the script needs N MiB by this line, ...".
std::string overMemoryBudget(std::uint64_t neededBytes, std::uint64_t budgetBytes);

// clang style: "file:line:col: error: message", then the source line and a
// caret under the column (omitted when the line is unknown). A message of
// the driver's (Diagnostic::fromDriver) ends in " [driver]".
// Lines are joined with '\n'; there is no newline after the last one.
std::string formatDiagnostic(const Diagnostic& d, const SourceTexts& sources);

const char* severityName(Severity s);

}  // namespace glimmer
