#include "process/batch.h"
#include "process/child_guard.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "backends/context.h"
#include "pipeline/console.h"
#include "pipeline/numeric_health.h"
#include "pipeline/prepare_script.h"
#include "image/image.h"
#include "plan/uniform_values.h"
#include "util/json.h"
#include "util/numbers.h"

namespace glimmer {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// One line of --report (util/json.h: how strings and numbers are written).
std::string resultJson(const BatchJob& job, int exitCode, const std::string& diagnostics, const std::string& written,
                       double prepareMs, double renderMs, double writeMs, const std::string& health) {
    auto ms = [](double v) { return jsonNumber(std::round(v * 100) / 100); };  // to the hundredth, as before
    Json line;
    line["script"] = job.script;
    line["exit"] = exitCode;
    line["output"] = written.empty() ? Json(nullptr) : Json(written);
    line["diagnostics"] = diagnostics;
    line["ms"] = {{"prepare", ms(prepareMs)}, {"render", ms(renderMs)}, {"write", ms(writeMs)}};
    line["health"] = health;
    return jsonLine(line);
}

// Sets one "name=value" of a grading setting. A range takes the value even
// outside the script's own range (the assignment's range is the
// solution's); anything else goes through --set's rules. False when no
// uniform has that name.
bool applyGradingAssignment(const Plan& plan, UniformValues& values, const std::string& assignment, Diagnostics& diags) {
    const std::string name = assignment.substr(0, assignment.find('='));
    bool found = false, plain = true;
    for (const auto& program : plan.programs)
        for (const auto& u : program.uniforms)
            if (u.name == name) found = true, plain = plain && u.form == UniformSetting::Form::Range;
    if (!found) return false;
    if (plain) {
        double v = 0;
        const std::string text = assignment.substr(name.size() + 1);
        auto [end, ec] = parseDouble(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size()) {
            for (size_t p = 0; p < plan.programs.size(); ++p)
                for (const auto& u : plan.programs[p].uniforms)
                    if (u.name == name) values.set(int(p), name, {v});
            return true;
        }
    }
    values.applySet(plan, assignment, diags, "--vary");
    return true;
}

// One script on a worker's context, as `glimmer render` draws it; a
// grading job once per setting.
BatchResult renderOne(const BatchJob& job, const BatchSettings& s, GlContext* context, const std::string& contextError) {
    // A grading job's diagnostics go into the teacher's report, which must
    // not change with -q (that is about the terminal). This is a worker
    // process: the parent's verbosity is untouched.
    if (!job.outputs.empty() && verbosity() == Verbosity::Quiet) setVerbosity(Verbosity::Normal);
    BatchResult r;
    Diagnostics diags;
    LoadedScript loaded;
    std::ostringstream printed;
    if (!context) {
        r.exitCode = 1;
        r.diagnostics = "glimmer: error: " + contextError + "\n";
        r.json = resultJson(job, 1, r.diagnostics, "", 0, 0, 0, "unchecked");
        return r;
    }
    ScriptRequest request;
    request.script = job.script;
    request.plan.includeDirs = s.includeDirs;
    request.plan.includeDirs.insert(request.plan.includeDirs.end(), job.includeDirs.begin(), job.includeDirs.end());
    request.plan.width = s.width;
    request.plan.height = s.height;
    request.plan.sandbox = s.sandbox;
    if (s.maxMemoryMiB > 0) request.plan.maxMemoryBytes = s.maxMemoryMiB << 20;
    auto t0 = Clock::now();
    auto renderer = prepareScript(request, [&](const char* n) { return context->getProcAddress(n); }, diags, loaded);
    double prepareMs = msSince(t0);
    printDiagnostics(diags, loaded.sources, printed);
    if (!renderer) {
        r.exitCode = 1;
        r.diagnostics = printed.str();
        r.ms = prepareMs;
        r.json = resultJson(job, 1, r.diagnostics, "", prepareMs, 0, 0, "unchecked");
        return r;
    }
    r.prepareMs = prepareMs;
    if (!job.outputs.empty()) {  // grading: every setting on this one renderer
        auto t1 = Clock::now();
        Diagnostics setDiags;
        std::set<std::string> seen;
        for (const auto& program : loaded.plan.programs)
            for (const auto& u : program.uniforms)
                if (u.form == UniformSetting::Form::Range && !u.values.empty() && seen.insert(u.name).second)
                    r.sliders.push_back(fmt::format("{} {:g} {:g} {:g}", u.name, u.min, u.values[0], u.max));
        for (size_t k = 0; k < job.settings.size() && k < job.outputs.size(); ++k) {
            const auto settingStart = Clock::now();
            UniformValues values(loaded.plan);
            for (const auto& a : job.settings[k])
                if (!applyGradingAssignment(loaded.plan, values, a, setDiags)) {
                    const std::string name = a.substr(0, a.find('='));
                    if (std::find(r.missing.begin(), r.missing.end(), name) == r.missing.end()) r.missing.push_back(name);
                }
            renderer->render(values, 0);
            std::string why;
            if (writePng(job.outputs[k], renderer->readScreen(), why)) r.written.push_back(job.outputs[k]);
            else printed << "glimmer: error: " << why << "\n";
            r.settingMs.push_back(msSince(settingStart));
        }
        printDiagnostics(setDiags, loaded.sources, printed);
        r.exitCode = r.written.size() == job.outputs.size() ? 0 : 1;
        r.diagnostics = printed.str();
        r.ms = prepareMs + msSince(t1);
        r.json = resultJson(job, r.exitCode, r.diagnostics, r.written.empty() ? "" : r.written[0], prepareMs,
                            msSince(t1), 0, "unchecked");
        return r;
    }
    auto t1 = Clock::now();
    renderer->render(UniformValues(loaded.plan), 0);
    Image screen = renderer->readScreen();
    double renderMs = msSince(t1);
    std::string health = "unchecked";
    if (s.strict) {
        bool bad = false;
        for (const auto& h : measureHealth(*renderer, loaded.plan)) bad |= h.bad();
        health = bad ? "bad" : "ok";
        if (bad) printed << "glimmer: error: --strict: a target holds NaN, Inf, negative or out-of-range values\n";
    }
    auto t2 = Clock::now();
    std::string why;
    bool wrote = health != "bad" && writePng(job.output, screen, why);
    if (health != "bad" && !wrote) printed << "glimmer: error: " << why << "\n";
    r.exitCode = wrote ? 0 : 1;
    r.diagnostics = printed.str();
    if (wrote) r.written.push_back(job.output);
    r.ms = prepareMs + renderMs + msSince(t2);
    r.json = resultJson(job, r.exitCode, r.diagnostics, wrote ? job.output : "", prepareMs, renderMs, msSince(t2), health);
    return r;
}

// A result as bytes for the pipe back to the parent: the four texts, each
// length-prefixed (lists joined by newlines), then the milliseconds.
std::string encodeResult(const BatchResult& r) {
    auto join = [](const std::vector<std::string>& v) {
        std::string out;
        for (const auto& x : v) out += (out.empty() ? "" : "\n") + x;
        return out;
    };
    std::string out;
    std::string times;
    for (double ms : r.settingMs) times += (times.empty() ? "" : "\n") + formatDouble(ms);
    times += (times.empty() ? "" : "\n") + formatDouble(r.prepareMs);  // the last line: the prepare's
    for (const std::string& text : {r.json, r.diagnostics, join(r.written), join(r.missing), join(r.sliders), times}) {
        std::uint32_t n = std::uint32_t(text.size());
        out.append(reinterpret_cast<const char*>(&n), sizeof n);
        out += text;
    }
    out.append(reinterpret_cast<const char*>(&r.ms), sizeof r.ms);
    return out;
}

bool decodeResult(const std::string& bytes, BatchResult& r) {
    size_t at = 0;
    auto text = [&](std::string& t) {
        std::uint32_t n = 0;
        if (at + sizeof n > bytes.size()) return false;
        std::memcpy(&n, bytes.data() + at, sizeof n);
        at += sizeof n;
        if (n > bytes.size() - at) return false;
        t = bytes.substr(at, n);
        at += n;
        return true;
    };
    auto split = [](const std::string& t) {
        std::vector<std::string> out;
        std::istringstream in(t);
        for (std::string l; std::getline(in, l);) out.push_back(l);
        return out;
    };
    std::string written, missing, sliders, times;
    if (!text(r.json) || !text(r.diagnostics) || !text(written) || !text(missing) || !text(sliders) || !text(times) ||
        at + sizeof r.ms != bytes.size())
        return false;
    std::memcpy(&r.ms, bytes.data() + at, sizeof r.ms);
    r.written = split(written);
    r.missing = split(missing);
    r.sliders = split(sliders);
    r.settingMs.clear();
    for (const std::string& line : split(times)) {  // locale-independent both ways (util/numbers.h)
        double ms = 0;
        if (parseDouble(line.data(), line.data() + line.size(), ms).ec != std::errc{}) return false;
        r.settingMs.push_back(ms);
    }
    if (r.settingMs.empty()) return false;
    r.prepareMs = r.settingMs.back();
    r.settingMs.pop_back();
    return true;
}

bool writeAll(int fd, const void* data, size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        ssize_t w = ::write(fd, p, n);
        if (w <= 0) return false;
        p += w;
        n -= size_t(w);
    }
    return true;
}

bool readAll(int fd, void* data, size_t n) {
    char* p = static_cast<char*>(data);
    while (n > 0) {
        ssize_t got = ::read(fd, p, n);
        if (got <= 0) return false;
        p += got;
        n -= size_t(got);
    }
    return true;
}

// A worker: reads job indices, renders, writes back {index, exit, length, json}.
[[noreturn]] void workerMain(int jobsFd, int resultsFd, const std::vector<BatchJob>& jobs, const BatchSettings& s) {
    std::unique_ptr<GlContext> context;
    std::string contextError;
    bool tried = false;
    std::uint32_t index = 0;
    while (readAll(jobsFd, &index, sizeof index)) {
        if (!tried) {  // made on the first job, kept for every later one
            tried = true;
            BackendChoice choice;
            if (parseBackend(s.backend, choice)) context = createContext(choice, contextError);
            else contextError = "unknown backend '" + s.backend + "'";
        }
        BatchResult r;
        try {
            r = renderOne(jobs[index], s, context.get(), contextError);
        } catch (const std::exception& e) {
            r.exitCode = 1;
            r.diagnostics = std::string("glimmer: error: ") + e.what() + "\n";
            r.json = resultJson(jobs[index], 1, r.diagnostics, "", 0, 0, 0, "unchecked");
        }
        std::int32_t code = r.exitCode;
        const std::string payload = encodeResult(r);
        std::uint32_t length = std::uint32_t(payload.size());
        if (!writeAll(resultsFd, &index, sizeof index) || !writeAll(resultsFd, &code, sizeof code) ||
            !writeAll(resultsFd, &length, sizeof length) || !writeAll(resultsFd, payload.data(), payload.size()))
            break;
    }
    std::fflush(nullptr);
    ::_exit(0);
}

struct Worker {
    pid_t pid = -1;
    int toWorker = -1, fromWorker = -1;
    long job = -1;  // the job it is rendering; -1: idle
    Clock::time_point started;
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
    return w;
}

void retire(Worker& w, bool kill) {
    if (w.pid > 0) {
        if (kill) ::kill(w.pid, SIGKILL);
        ::close(w.toWorker);
        ::close(w.fromWorker);
        int status = 0;
        ::waitpid(w.pid, &status, 0);
    }
    w = Worker{};
}

}  // namespace

size_t settingsDrawn(const BatchJob& job) {
    size_t drawn = 0;
    std::error_code ec;
    while (drawn < job.outputs.size() && std::filesystem::exists(job.outputs[drawn], ec)) ++drawn;
    return drawn;
}

bool inShard(size_t index, int shard, int shards) {
    return shards >= 1 && shard >= 1 && shard <= shards && int(index % size_t(shards)) == shard - 1;
}

namespace {

// The length of the UTF-8 character beyond ASCII at `k` of `s`, when it is a
// whole one and not a C1 control; 0 otherwise.
size_t utf8Letter(const std::string& s, size_t k) {
    const unsigned char c = static_cast<unsigned char>(s[k]);
    const size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (n == 0 || k + n > s.size()) return 0;
    for (size_t i = 1; i < n; ++i)
        if ((static_cast<unsigned char>(s[k + i]) & 0xC0) != 0x80) return 0;
    if (c == 0xC2 && static_cast<unsigned char>(s[k + 1]) <= 0x9F) return 0;  // C1
    return n;
}

}  // namespace

std::vector<std::string> batchOutputNames(const std::vector<std::string>& scripts) {
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
                         c == '_' || c == '.';
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
        while (!name.empty() && (name.front() == '_' || name.front() == '.')) name.erase(0, 1);
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
    std::vector<BatchResult> results(jobs.size());
    std::vector<bool> done(jobs.size(), false);
    size_t next = 0, finished = 0;
    ::signal(SIGPIPE, SIG_IGN);  // a worker that died mid-job must not take the parent with it
    std::vector<Worker> workers(size_t(std::max(1, std::min<int>(s.jobs, int(jobs.size())))));
    auto ranMs = [](const Worker& w) { return std::chrono::duration<double, std::milli>(Clock::now() - w.started).count(); };
    // `ms`: how long the job ran before it was stopped (a time-out is not
    // "0.00 s" in a report: issue 29).
    auto fail = [&](long job, const std::string& why, double ms = 0) {
        const BatchJob& j = jobs[size_t(job)];
        BatchResult& r = results[size_t(job)];
        r.exitCode = 1;
        r.json = resultJson(j, 1, why, "", 0, 0, 0, "unchecked");
        r.diagnostics = why;
        r.ms = ms;
        done[size_t(job)] = true;
        ++finished;
        if (onResult) onResult(size_t(job), r);
        if (progress) progress(finished, jobs.size());
    };
    auto assign = [&](Worker& w) {
        if (next >= jobs.size()) return;
        if (w.pid <= 0) w = spawn(jobs, s, workers);
        if (w.pid <= 0) return;
        std::uint32_t index = std::uint32_t(next);
        if (!writeAll(w.toWorker, &index, sizeof index)) {
            retire(w, true);
            return;
        }
        w.job = long(next++);
        w.started = Clock::now();
    };
    for (auto& w : workers) assign(w);
    while (finished < jobs.size()) {
        std::vector<pollfd> fds;
        for (auto& w : workers) fds.push_back({w.pid > 0 ? w.fromWorker : -1, POLLIN, 0});
        ::poll(fds.data(), fds.size(), 50);
        for (size_t k = 0; k < workers.size(); ++k) {
            Worker& w = workers[k];
            if (w.pid <= 0) {
                if (next < jobs.size()) assign(w);
                continue;
            }
            if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) {
                std::uint32_t index = 0, length = 0;
                std::int32_t code = 0;
                std::string payload;
                BatchResult got;
                bool ok = readAll(w.fromWorker, &index, sizeof index) && readAll(w.fromWorker, &code, sizeof code) &&
                          readAll(w.fromWorker, &length, sizeof length) && length < (64u << 20);
                if (ok) {
                    payload.resize(length);
                    ok = readAll(w.fromWorker, payload.data(), length) && long(index) == w.job &&
                         decodeResult(payload, got);
                }
                if (ok) {
                    got.exitCode = code;
                    results[index] = std::move(got);
                    done[index] = true;
                    ++finished;
                    if (onResult) onResult(index, results[index]);
                    if (progress) progress(finished, jobs.size());
                    w.job = -1;
                    if (next < jobs.size()) assign(w);
                    else retire(w, false);
                } else {
                    long job = w.job;
                    const double ms = ranMs(w);
                    retire(w, true);
                    if (job >= 0 && !done[size_t(job)])
                        fail(job, jobs[size_t(job)].script + ": error: the renderer crashed while drawing this script\n",
                             ms);
                    if (next < jobs.size()) assign(w);
                }
                continue;
            }
            // The limit now: the whole job's, or (grading) that of the setting it is drawing.
            double limit = s.timeoutSeconds;
            if (w.job >= 0 && !s.settingDeadlines.empty() &&
                s.settingDeadlines.size() == jobs[size_t(w.job)].outputs.size()) {
                limit = s.settingDeadlines[std::min(settingsDrawn(jobs[size_t(w.job)]), s.settingDeadlines.size() - 1)];
            }
            if (const double ms = ranMs(w); w.job >= 0 && limit > 0 && ms > limit * 1000) {
                long job = w.job;
                retire(w, true);
                fail(job, fmt::format("{}: error: stopped after {:g} s ({})\n", jobs[size_t(job)].script, limit,
                                      s.timeoutSaid.empty() ? fmt::format("--timeout {:g}", s.timeoutSeconds)
                                                            : s.timeoutSaid), ms);
                if (next < jobs.size()) assign(w);
            }
        }
    }
    for (auto& w : workers) retire(w, false);
    return results;
}

}  // namespace glimmer
