// --timeout: a script's GL work in a child process the parent can stop.
//
// Why a process: llvmpipe cannot be interrupted in the middle of a draw (a
// fragment shader that loops for minutes holds the thread inside the
// driver), and no GL call cancels queued work. A child process can always
// be killed. The child reports each pass as it starts (its script line),
// and finishes each pass before announcing the next, so the parent can name
// the pass that was still drawing when time ran out. The parent makes no GL
// context; the child inherits stdin, stdout and stderr and writes every
// output itself.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "lang/diagnostics.h"

namespace glimmer {

// Runs `work` (returns an exit code) in a child process and waits at most
// `seconds` (0: no limit). On time-out the child is killed and the message
// names `script` and the line of the pass that was drawing; a child killed
// by a signal is reported too. Returns the exit code. The child dies with
// this process and, with `addressSpaceBytes` > 0 (--sandbox), may map at
// most that much (process/child_guard.h). With neither a time nor an address
// limit, `work` runs here.
int runWithTimeout(double seconds, const std::string& script, const std::function<int()>& work,
                   std::uint64_t addressSpaceBytes = 0);

// In the child: reports that the pass written at `loc` starts. Does nothing
// outside runWithTimeout.
void reportPassStart(SourceLoc loc);
// Whether passes should be reported (a watchdog is waiting for them).
bool passesWatched();

}  // namespace glimmer
