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
};

// Renders every job; `progress(done, total)` after each, and
// `onResult(index, result)` as each result arrives (in the order they
// finish, so a caller can save it at once). Never throws.
std::vector<BatchResult> runBatch(const std::vector<BatchJob>& jobs, const BatchSettings& settings,
                                  const std::function<void(size_t, size_t)>& progress,
                                  const std::function<void(size_t, const BatchResult&)>& onResult = {});

// How many of a grading job's settings are drawn: its outputs are written
// in order, so the count of those on disk from the first (a stopped job's
// tells where it stopped; the per-setting limits which one it is drawing).
size_t settingsDrawn(const BatchJob& job);

// Whether position `index` of the list belongs to shard `shard` (1-based) of `shards`.
bool inShard(size_t index, int shard, int shards);

// One PNG name per script, derived from its path ("class/alice/bloom.glib"
// -> "class_alice_bloom.png"; letters beyond ASCII kept as written in UTF-8),
// made unique with "-2", "-3", ... in list order.
std::vector<std::string> batchOutputNames(const std::vector<std::string>& scripts);

}  // namespace glimmer
