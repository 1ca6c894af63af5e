#include "process/batch.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <set>

#include <fmt/format.h>

#include "lang/diagnostics.h"
#include "process/batch_worker.h"
#include "process/child_guard.h"
#include "util/json.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct Worker {
    pid_t pid = -1;
    int toWorker = -1, fromWorker = -1;
    long job = -1;       // the job it is drawing; -1: idle
    int jobsTaken = 0;   // a fresh worker has taken none
    bool begun = false;  // the worker said it began the job (its context is made)
    int phase = kPhasePreparing;
    bool tainted = false;  // another worker was killed while this job was in flight
    bool shared = false;   // another worker drew while this job was in flight
    Clock::time_point since;  // spawned, or began the job
};

// `others`: the workers already running. A child inherits their pipe ends
// and must close them, or a worker the parent lets go never sees the end of
// its job pipe (another worker would still hold it open).
Worker spawn(const std::vector<BatchJob>& jobs, const BatchSettings& s, const std::vector<Worker>& others) {
    int down[2], up[2];
    Worker w;
    if (::pipe(down) != 0) return w;
    if (::pipe(up) != 0) {
        ::close(down[0]);
        ::close(down[1]);
        return w;
    }
    std::fflush(nullptr);
    const pid_t parent = ::getpid();
    pid_t pid = ::fork();
    if (pid == 0) {
        // Dies with the batch; under --sandbox (grading's default) its
        // address space is bounded too (process/child_guard.h).
        guardChild(parent, s.sandbox ? sandboxAddressSpaceBytes(s.maxMemoryMiB) : 0);
        ::close(down[1]);
        ::close(up[0]);
        for (const Worker& o : others)
            if (o.pid > 0) {
                ::close(o.toWorker);
                ::close(o.fromWorker);
            }
        workerMain(down[0], up[1], jobs, s);
    }
    ::close(down[0]);
    ::close(up[1]);
    w.pid = pid;
    w.toWorker = down[1];
    w.fromWorker = up[0];
    w.since = Clock::now();
    return w;
}

// Lets a worker go: killed, or told there is no more work (its job pipe
// closed). Not waited for here: a process killed inside the GPU driver can
// take many seconds to end (NVIDIA: in the kernel, holding a lock the other
// workers need), and every other worker's clock runs meanwhile. Reaped by
// reapSome, and by reapAll at the end.
void retire(Worker& w, bool kill, std::vector<pid_t>& ending) {
    if (w.pid > 0) {
        if (kill) ::kill(w.pid, SIGKILL);
        ::close(w.toWorker);
        ::close(w.fromWorker);
        ending.push_back(w.pid);
    }
    w = Worker{};
}

void reapSome(std::vector<pid_t>& ending) {
    ending.erase(std::remove_if(ending.begin(), ending.end(),
                                [](pid_t p) {
                                    int status = 0;
                                    return ::waitpid(p, &status, WNOHANG) != 0;
                                }),
                 ending.end());
}

void reapAll(std::vector<pid_t>& ending) {
    for (pid_t p : ending) {
        int status = 0;
        ::waitpid(p, &status, 0);
    }
    ending.clear();
}

// What a stopped job was doing, for its message.
std::string stoppedWhile(const BatchJob& job, int phase) {
    if (phase == kPhasePreparing) return "while loading and compiling the script";
    if (!job.outputs.empty()) return fmt::format("while drawing setting {} of {}", phase + 1, job.outputs.size());
    return "while drawing";
}

// The scheduler: which job goes to which worker, and what a worker's
// answer, crash or time-out means (batch.h's contract).
class Scheduler {
public:
    Scheduler(const std::vector<BatchJob>& jobs, const BatchSettings& s,
              const std::function<void(size_t, size_t)>& progress,
              const std::function<void(size_t, const BatchResult&)>& onResult)
        : jobs_(jobs), s_(s), progress_(progress), onResult_(onResult), results_(jobs.size()), state_(jobs.size()),
          workers_(size_t(std::max(1, std::min<int>(s.jobs, int(jobs.size()))))) {
        for (size_t k = 0; k < jobs.size(); ++k) queue_.push_back(k);
    }

    std::vector<BatchResult> run() {
        ::signal(SIGPIPE, SIG_IGN);  // a worker that died mid-job must not take the parent with it
        while (finished_ < jobs_.size()) {
            assign();
            std::vector<pollfd> fds;
            for (auto& w : workers_) fds.push_back({w.pid > 0 ? w.fromWorker : -1, POLLIN, 0});
            ::poll(fds.data(), fds.size(), 50);
            for (size_t k = 0; k < workers_.size(); ++k) {
                Worker& w = workers_[k];
                if (w.pid <= 0) continue;
                if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) hear(w);
                else checkTime(w);
            }
            reapSome(ending_);
        }
        for (auto& w : workers_) retire(w, false, ending_);
        reapAll(ending_);
        return std::move(results_);
    }

private:
    struct JobState {
        bool retried = false;    // drawn again alone once already
        bool alone = false;      // must be drawn with no other worker drawing, in a fresh worker
    };

    bool loneJobRunning() const {
        for (const Worker& w : workers_)
            if (w.job >= 0 && state_[size_t(w.job)].alone) return true;
        return false;
    }
    bool anyBusy() const {
        for (const Worker& w : workers_)
            if (w.job >= 0) return true;
        return false;
    }

    void give(Worker& w, size_t job) {
        if (w.pid <= 0) w = spawn(jobs_, s_, workers_);
        if (w.pid <= 0) return;
        std::uint32_t index = std::uint32_t(job);
        if (!writeAll(w.toWorker, &index, sizeof index)) {
            retire(w, true, ending_);
            return;
        }
        queue_.pop_front();
        w.shared = false;
        for (Worker& o : workers_)
            if (&o != &w && o.job >= 0) o.shared = w.shared = true;
        w.job = long(job);
        w.begun = false;
        w.phase = kPhasePreparing;
        w.tainted = false;
        ++w.jobsTaken;
        if (w.jobsTaken > 1) w.since = Clock::now();  // a fresh worker's clock runs from its spawn until it begins
    }

    void assign() {
        while (!queue_.empty() && !loneJobRunning()) {
            const size_t job = queue_.front();
            if (state_[job].alone) {
                if (anyBusy()) return;  // wait for the others to finish
                Worker& w = workers_[0];
                if (w.pid > 0 && w.jobsTaken > 0) retire(w, false, ending_);
                give(w, job);
                return;
            }
            Worker* idle = nullptr;
            for (Worker& w : workers_)
                if (w.job < 0 && !idle) idle = &w;
            if (!idle) return;
            const size_t before = queue_.size();
            give(*idle, job);
            if (queue_.size() == before) return;  // no worker could be started: try again next round
        }
    }

    void finish(size_t job, BatchResult r) {
        r.drawnAlone = state_[job].retried;
        results_[job] = std::move(r);
        ++finished_;
        if (onResult_) onResult_(job, results_[job]);
        if (progress_) progress_(finished_, jobs_.size());
    }

    // The job's one second drawing: next, alone, in a fresh worker.
    void drawAgainAlone(size_t job) {
        state_[job].retried = true;
        state_[job].alone = true;
        queue_.push_front(job);
    }

    // A job the machine failed: drawn again alone, once; then final. Once a
    // lone worker could not make a context either, no later job waits for
    // a second try of that (the backend is missing, not busy).
    void machineFailed(size_t job, BatchResult r) {
        const bool noContext = r.failure.rfind(kNoContext, 0) == 0;
        if (state_[job].retried && noContext) contextMissing_ = true;
        if (!state_[job].retried && !(noContext && contextMissing_)) {
            drawAgainAlone(job);
            return;
        }
        if (state_[job].retried) {
            r.diagnostics += "glimmer: note: the same when drawn again, alone on the machine in a fresh worker\n";
            Json line = Json::parse(r.json, nullptr, false);
            if (line.is_object()) {
                line["diagnostics"] = r.diagnostics;
                r.json = jsonLine(line);
            }
        }
        finish(job, std::move(r));
    }

    // Every other job in flight when a worker is killed may have lost its
    // work or its time to it: drawn again.
    void taintOthers(const Worker& killed) {
        for (Worker& w : workers_)
            if (&w != &killed && w.job >= 0) w.tainted = true;
    }

    void requeueTainted(Worker& w) {
        queue_.push_front(size_t(w.job));
        retire(w, false, ending_);
    }

    void hear(Worker& w) {
        WorkerMessage m;
        std::string payload;
        bool ok = readAll(w.fromWorker, &m, sizeof m) && m.length < (64u << 20) && long(m.job) == w.job;
        if (ok) {
            payload.resize(m.length);
            ok = readAll(w.fromWorker, payload.data(), m.length);
        }
        BatchResult got;
        if (ok && m.kind == WorkerMessage::Phase) {
            if (!w.begun) w.since = Clock::now();  // the job's own time starts now
            w.begun = true;
            w.phase = m.a;
            return;
        }
        ok = ok && m.kind == WorkerMessage::Result && decodeResult(payload, got);
        const long job = w.job;
        if (!ok) {  // a crash, or garbage on the pipe
            const double ms = w.begun ? msSince(w.since) : 0;
            const bool tainted = w.tainted;
            const int phase = w.phase;
            retire(w, true, ending_);
            taintOthers(w);
            if (job < 0) return;
            if (tainted) {
                queue_.push_front(size_t(job));
                return;
            }
            BatchResult r = failed(size_t(job), jobs_[size_t(job)].script + ": error: the renderer crashed " +
                                                    stoppedWhile(jobs_[size_t(job)], phase) + "\n", ms);
            r.stoppedAt = phase;
            machineFailed(size_t(job), std::move(r));
            return;
        }
        got.exitCode = m.a;
        if (w.tainted) {
            requeueTainted(w);
            return;
        }
        w.job = -1;
        if (!got.failure.empty()) {  // the worker said its context failed: it is ending
            retire(w, false, ending_);
            machineFailed(size_t(job), std::move(got));
            return;
        }
        if (s_.recheck && !state_[size_t(job)].retried && s_.recheck(size_t(job), got)) {
            drawAgainAlone(size_t(job));
            return;
        }
        finish(size_t(job), std::move(got));
    }

    void checkTime(Worker& w) {
        if (w.job < 0) return;
        const BatchJob& job = jobs_[size_t(w.job)];
        double limit = contextLimit_;
        if (w.begun) {
            // The limit now: the whole job's, or (grading) that of the setting it is drawing.
            limit = s_.timeoutSeconds;
            if (!s_.settingDeadlines.empty() && s_.settingDeadlines.size() == job.outputs.size())
                limit = s_.settingDeadlines[size_t(std::clamp<int>(w.phase, 0, int(s_.settingDeadlines.size()) - 1))];
        }
        const double ms = msSince(w.since);
        if (!(limit > 0) || ms <= limit * 1000) return;
        const size_t index = size_t(w.job);
        const bool begun = w.begun, tainted = w.tainted, shared = w.shared;
        const int phase = w.phase;
        retire(w, true, ending_);
        taintOthers(w);
        BatchResult r;
        if (!begun)
            // Seen on the lent H200: a worker killed while drawing stayed in the
            // NVIDIA driver's lock for minutes, and every new context on the
            // machine waited behind it (issue 36).
            r = failed(index, fmt::format("{}: error: the worker could not make its GL context in {:g} s\n"
                                          "glimmer: note: on a GPU, a process stuck in the driver (one killed while "
                                          "drawing, say) holds every new context: `ps -eo pid,stat,wchan,args` shows "
                                          "it in state D\n", job.script, limit), 0);
        else
            r = failed(index,
                       fmt::format("{}: error: stopped after {:g} s ({}) {}\n", job.script, limit,
                                   s_.timeoutSaid.empty() ? fmt::format("--timeout {:g}", s_.timeoutSeconds) : s_.timeoutSaid,
                                   stoppedWhile(job, phase)),
                       ms);
        r.stoppedAt = begun ? phase : BatchResult::kNotStopped;
        if (!begun) r.failure = std::string(kNoContext) + "not made in time";
        // A job that had the machine to itself the whole time has had its
        // lone drawing: its time-out is final (a second one would cost the
        // limit again, and on NVIDIA a second kill of a shader that never
        // ends holds every other process in the driver for seconds). A
        // tainted job is retried like any other: every kill costs a retry.
        if (begun && !shared && !tainted) finish(index, std::move(r));
        else machineFailed(index, std::move(r));
    }

    BatchResult failed(size_t job, const std::string& why, double ms) {
        BatchResult r;
        r.exitCode = 1;
        r.json = failedResultJson(jobs_[job], why);
        r.diagnostics = why;
        r.ms = ms;
        return r;
    }

    const std::vector<BatchJob>& jobs_;
    const BatchSettings& s_;
    const std::function<void(size_t, size_t)>& progress_;
    const std::function<void(size_t, const BatchResult&)>& onResult_;
    std::vector<BatchResult> results_;
    std::vector<JobState> state_;
    std::vector<Worker> workers_;
    std::deque<size_t> queue_;
    std::vector<pid_t> ending_;
    size_t finished_ = 0;
    bool contextMissing_ = false;
    const double contextLimit_ = contextLimitSeconds(s_);  // read once: checkTime runs on every poll
};

}  // namespace


bool inShard(size_t index, int shard, int shards) {
    return shards >= 1 && shard >= 1 && shard <= shards && int(index % size_t(shards)) == shard - 1;
}

namespace {

// The length of the UTF-8 character beyond ASCII at `k` of `s`, when it is a
// whole one and not a C1 control; 0 otherwise.
size_t utf8Letter(const std::string& s, size_t k) {
    const size_t n = utf8Length(s, k);
    if (n == 2 && static_cast<unsigned char>(s[k]) == 0xC2 && static_cast<unsigned char>(s[k + 1]) <= 0x9F) return 0;  // C1
    return n;
}

}  // namespace

std::vector<std::string> batchOutputNames(const std::vector<std::string>& scripts, bool keepSpaces) {
    std::vector<std::string> out;
    std::set<std::string> used;
    for (const auto& s : scripts) {
        std::string base = s;
        if (base.size() > 5 && base.compare(base.size() - 5, 5, ".glib") == 0) base.resize(base.size() - 5);
        while (base.rfind("./", 0) == 0) base.erase(0, 2);
        std::string name;
        for (size_t k = 0; k < base.size();) {
            const unsigned char c = static_cast<unsigned char>(base[k]);
            bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                         c == '_' || c == '.' || (keepSpaces && (c == ' ' || c == '(' || c == ')'));
            // A name keeps its letters as written in UTF-8 (Jürgen, 李雷: issue 29,
            // they were J__rgen and 'script'); a byte that is not part of a
            // whole UTF-8 character, or a C1 control (U+0080..U+009F), is '_'.
            if (size_t n = utf8Letter(base, k)) {
                name.append(base, k, n);
                k += n;
                continue;
            }
            name += plain ? char(c) : '_';
            ++k;
        }
        while (!name.empty() && (name.front() == '_' || name.front() == '.' || name.front() == ' ')) name.erase(0, 1);
        while (!name.empty() && name.back() == ' ') name.pop_back();
        if (name.empty()) name = "script";
        std::string unique = name;
        for (int k = 2; used.count(unique); ++k) unique = fmt::format("{}-{}", name, k);
        used.insert(unique);
        out.push_back(unique + ".png");
    }
    return out;
}

std::vector<BatchResult> runBatch(const std::vector<BatchJob>& jobs, const BatchSettings& s,
                                  const std::function<void(size_t, size_t)>& progress,
                                  const std::function<void(size_t, const BatchResult&)>& onResult) {
    return Scheduler(jobs, s, progress, onResult).run();
}

}  // namespace glimmer
