// glimmer batch: many scripts rendered by a pool of worker processes, each
// keeping one GL context for every script it renders (a context and the
// driver's start-up cost more than a small script's whole render).
//
// Contract:
//   - Results come back in the order of the jobs, one per job, whatever
//     happens to a worker: a script that crashes its worker or runs past
//     the time limit is a failed result and the worker is replaced; no
//     other script is lost.
//   - The parent makes no GL context; workers are forked before any.
//   - A result is one the machine drew cleanly, or the script's own failure
//     seen twice. Workers share one GPU, and on a GPU one process can stall
//     or reset the others' work (a shader that never ends, a worker killed
//     mid-draw: on NVIDIA the others then read back zeros or wait for ever).
//     So: a job stopped by the time limit, a crashed worker, or a context
//     that reports a reset, a lost context or no memory (BatchResult::
//     failure) is drawn once more, alone (no other worker drawing) in a
//     fresh worker, and only that second outcome counts; every job that was
//     in flight while a worker was killed is drawn again (not counted as a
//     retry), and its worker is replaced. A worker that failed is never
//     reused. `BatchSettings::recheck` asks for the same second, lone
//     drawing of a result that looks suspicious to the caller (grading: a
//     picture that is a single colour).
//   - shardOf is a pure function of the position in the list, so N machines
//     given the same list and I = 1..N render each script exactly once.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace glimmer {

struct BatchJob {
    std::string script;  // the .glib file
    std::string output;  // the PNG to write
    // Grading (app/grade_batch.cpp): the script drawn once per setting
    // ("name=value" assignments; empty: the script's own values) into
    // outputs[k], on the one renderer, instead of once into `output`. A
    // range is set even outside the script's own range (the assignment's
    // range is the solution's); a name no uniform of the script has is
    // skipped and reported in BatchResult::missing.
    std::vector<std::vector<std::string>> settings;
    std::vector<std::string> outputs;
    // More folders this job may read, after BatchSettings::includeDirs
    // (grading: the submission's own folder, so that under --sandbox a
    // script three folders down still reaches its submission's other files).
    std::vector<std::string> includeDirs;
};

struct BatchResult;

struct BatchSettings {
    std::string backend = "auto";
    std::vector<std::string> includeDirs;
    int width = 0, height = 0;     // 0: the script's size
    bool sandbox = false;
    std::uint64_t maxMemoryMiB = 0;
    double timeoutSeconds = 0;     // per script; 0: none
    // How a stop names the limit, in parentheses after "stopped after N s";
    // empty: "--timeout N" (grading's own default limit is no --timeout).
    std::string timeoutSaid;
    // Grading: a limit per setting instead of one for the whole job. Entry
    // k is the time (s, from the job's start) by which its setting k must be
    // drawn; while a job has written k of its outputs (they are written in
    // order) it may run until entry k. Empty: timeoutSeconds alone.
    std::vector<double> settingDeadlines;
    bool strict = false;           // a target with NaN, Inf, negatives or out-of-range values fails the script
    int jobs = 2;                  // worker processes
    // Called in the parent with a finished job's result: true to have it
    // drawn once more, alone in a fresh worker, whose result is then final.
    std::function<bool(std::size_t job, const BatchResult&)> recheck;
    // How long a fresh worker may take to make its GL context before it is
    // replaced (not counted in any script's time).
    double contextSeconds = 60;
};

struct BatchResult {
    int exitCode = 0;              // as `glimmer render` would exit
    std::string json;              // one JSON object: script, exit, output, diagnostics, ms, health
    // The same, as values, for grading:
    std::string diagnostics;            // as printed (file:line:col: ..., the source line, a caret)
    std::vector<std::string> written;   // the PNGs written (outputs of a grading job, in order)
    std::vector<std::string> missing;   // uniforms a setting names that the script lacks
    // Grading: the script's sliders, "NAME MIN DEFAULT MAX" each (compared
    // with the solution's), and each setting's render and write in ms (the
    // solution's set the time limits, app/grade_batch.cpp).
    std::vector<std::string> sliders;
    std::vector<double> settingMs;
    double prepareMs = 0;
    double ms = 0;                      // prepare, render and write together
    // Why the machine, not the script, failed (a GPU reset, a lost context,
    // no GPU memory, no context): "" when it did not. Set by the worker;
    // runBatch retries such a job, and a final result keeps it.
    std::string failure;
    // Where a stopped job was: kNotStopped, kStoppedPreparing (loading and
    // compiling), or the setting being drawn (0 for a plain script).
    static constexpr int kNotStopped = -2, kStoppedPreparing = -1;
    int stoppedAt = kNotStopped;
    bool drawnAlone = false;            // this result is the second, lone drawing
};

// Renders every job; `progress(done, total)` after each, and
// `onResult(index, result)` as each result arrives (in the order they
// finish, so a caller can save it at once). Never throws.
std::vector<BatchResult> runBatch(const std::vector<BatchJob>& jobs, const BatchSettings& settings,
                                  const std::function<void(size_t, size_t)>& progress,
                                  const std::function<void(size_t, const BatchResult&)>& onResult = {});


// Whether position `index` of the list belongs to shard `shard` (1-based) of `shards`.
bool inShard(size_t index, int shard, int shards);

// One PNG name per script, derived from its path ("class/alice/bloom.glib"
// -> "class_alice_bloom.png"; letters beyond ASCII kept as written in UTF-8),
// made unique with "-2", "-3", ... in list order.
// With `keepSpaces` (grading's student names: "Jürgen Groß" as written,
// issue 37) a space inside a name is kept, and parentheses; leading and
// trailing spaces go.
std::vector<std::string> batchOutputNames(const std::vector<std::string>& scripts, bool keepSpaces = false);

}  // namespace glimmer
