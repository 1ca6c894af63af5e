// One worker of `glimmer batch` (process/batch.h): a forked process that
// makes its GL context first, then draws the jobs the parent sends it, one
// at a time, and says what it is doing as it goes.
//
// The pipe between them (both ends on one machine, native byte order):
//   parent -> worker: a job index (uint32) per job.
//   worker -> parent: messages, each a WorkerMessage head then `length`
//     bytes: Phase (the job's preparing, a = -1, or its setting a being
//     drawn; no bytes) and Result (a = the exit code; the bytes are
//     encodeResult's).
// Why the phases: the parent's clock for a job starts when the worker
// begins it, not while a fresh worker makes its context (on a GPU shared by
// eight processes that can take seconds), and a stop names what was running.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "process/batch.h"

namespace glimmer {

struct WorkerMessage {
    enum Kind : std::uint32_t { Phase = 1, Result = 2 };
    std::uint32_t kind = 0;
    std::uint32_t job = 0;
    std::int32_t a = 0;
    std::uint32_t length = 0;
};
constexpr std::int32_t kPhasePreparing = -1;
// How BatchResult::failure begins when the worker has no GL context.
constexpr const char* kNoContext = "no GL context: ";

// How long a worker may take to make its context: s.contextSeconds, or 2 s
// under the test hook's fault "stuck" (batch_worker.cpp), so a test of a
// worker stuck in the driver does not wait a minute.
double contextLimitSeconds(const BatchSettings& s);

// Runs in the forked child; never returns.
[[noreturn]] void workerMain(int jobsFd, int resultsFd, const std::vector<BatchJob>& jobs, const BatchSettings& s);

// A result as bytes and back (the texts length-prefixed, then the numbers).
std::string encodeResult(const BatchResult& r);
bool decodeResult(const std::string& bytes, BatchResult& r);

// The --report line of a script that failed before any worker drew it.
std::string failedResultJson(const BatchJob& job, const std::string& diagnostics);

bool writeAll(int fd, const void* data, std::size_t n);
bool readAll(int fd, void* data, std::size_t n);

}  // namespace glimmer
