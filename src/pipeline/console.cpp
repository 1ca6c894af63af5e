#include "pipeline/console.h"

#include <unistd.h>

#include <cstdlib>
#include <iostream>

namespace glimmer {
namespace {
Verbosity g_verbosity = Verbosity::Verbose;
}

Verbosity verbosity() { return g_verbosity; }
void setVerbosity(Verbosity v) { g_verbosity = v; }

bool stderrIsTerminal() {
    if (const char* e = std::getenv("GLIMMER_TTY"); e && *e) return e[0] == '1';
    return ::isatty(STDERR_FILENO) == 1;
}

Progress::~Progress() { finish(); }

void Progress::update(const std::string& text) {
    if (verbosity() == Verbosity::Quiet) return;
    if (!stderrIsTerminal()) {
        std::cerr << text << "\n";
        return;
    }
    // Pad over a longer line before it.
    std::string line = text;
    if (line.size() < width_) line.append(width_ - line.size(), ' ');
    width_ = text.size();
    std::cerr << "\r" << line << std::flush;
    open_ = true;
}

void Progress::finish() {
    if (open_) std::cerr << "\n";
    open_ = false;
}

void reportWrote(const std::string& what) {
    if (verbosity() != Verbosity::Quiet) std::cerr << "wrote " << what << "\n";
}

void printWarning(std::ostream& out, const std::string& line) {
    if (line.empty() || verbosity() == Verbosity::Quiet) return;
    out << line << "\n";
}

}  // namespace glimmer
