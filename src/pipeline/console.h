// How much the command line says on stderr, and how: -q (errors only), the
// default (repeated glman-compatibility warnings folded into one line each),
// -v (every warning listed). Progress lines rewrite themselves with '\r' only
// on a terminal; in a log each is a line of its own.
#pragma once
#include <iosfwd>
#include <string>

namespace glimmer {

enum class Verbosity { Quiet, Normal, Verbose };

// Verbose (everything, unfolded) until a front end chooses: library users and
// tests see every diagnostic.
Verbosity verbosity();
void setVerbosity(Verbosity v);

// Whether standard error is a terminal (tests may pretend: GLIMMER_TTY=1).
bool stderrIsTerminal();

// "sheet: 3/9 rendered": on a terminal one line rewritten in place, else one
// line each; nothing under -q.
class Progress {
public:
    ~Progress();
    void update(const std::string& text);
    void finish();  // ends the terminal line; called by the destructor too

private:
    bool open_ = false;
    size_t width_ = 0;
};

// The one line every command prints about what it wrote ("wrote out.png
// (512x512)"), on stderr; nothing under -q.
void reportWrote(const std::string& what);

// A warning line made elsewhere (e.g. gl_api.h's refusedCallWarning) onto
// `out`, with its newline; nothing when it is empty or under -q. One place for
// the -q rule, so render and batch's two paths cannot disagree on it.
void printWarning(std::ostream& out, const std::string& line);

}  // namespace glimmer
