#include "process/batch_worker.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "backends/context.h"
#include "image/image.h"
#include "pipeline/console.h"
#include "pipeline/numeric_health.h"
#include "pipeline/prepare_script.h"
#include "plan/uniform_values.h"
#include "process/test_fault.h"
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

// GLIMMER_TEST_FAULT=stuck:context: (process/test_fault.h) a worker that
// never finishes making its context.
void stickIfAsked() {
    const std::optional<TestFault> f = testFaultAsked();
    if (!f || f->kind != "stuck" || f->part != "context" || !takesTestFault(*f)) return;
    for (;;) ::pause();  // until the parent's kill
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
BatchResult renderOne(const BatchJob& job, const BatchSettings& s, GlContext* context, const std::string& contextError,
                      const std::function<void(int)>& phase) {
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
        r.failure = kNoContext + contextError;
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
            phase(int(k));
            UniformValues values(loaded.plan);
            for (const auto& a : job.settings[k])
                if (!applyGradingAssignment(loaded.plan, values, a, setDiags)) {
                    const std::string name = a.substr(0, a.find('='));
                    if (std::find(r.missing.begin(), r.missing.end(), name) == r.missing.end()) r.missing.push_back(name);
                }
            renderer->render(values, 0);
            Image picture = renderer->readScreen();
            // A picture the GPU lost is no picture of the script's: no file,
            // no grade (the parent draws the job again in a fresh worker).
            std::string refused;
            r.failure = pictureFailure(*renderer, job.script, picture, &refused);
            if (!r.failure.empty()) {
                printed << "glimmer: error: " << r.failure << "\n";
                break;
            }
            printWarning(printed, refused);
            std::string why;
            if (writePng(job.outputs[k], picture, why)) r.written.push_back(job.outputs[k]);
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
    phase(0);
    renderer->render(UniformValues(loaded.plan), 0);
    Image screen = renderer->readScreen();
    double renderMs = msSince(t1);
    std::string refused;
    r.failure = pictureFailure(*renderer, job.script, screen, &refused);
    if (!r.failure.empty()) {
        r.exitCode = 1;
        r.diagnostics = printed.str() + "glimmer: error: " + r.failure + "\n";
        r.json = resultJson(job, 1, r.diagnostics, "", prepareMs, renderMs, 0, "unchecked");
        return r;
    }
    printWarning(printed, refused);
    std::string health = "unchecked";
    if (s.strict) {
        // Only the bad targets' lines, as render --health prints them: a
        // class's report would otherwise carry every target of every script.
        bool bad = false;
        for (const auto& h : measureHealth(*renderer, loaded.plan)) {
            if (h.bad()) printed << formatHealth(h) << "\n";
            bad |= h.bad();
        }
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

}  // namespace

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
    for (const std::string& text :
         {r.json, r.diagnostics, join(r.written), join(r.missing), join(r.sliders), times, r.failure}) {
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
    if (!text(r.json) || !text(r.diagnostics) || !text(written) || !text(missing) || !text(sliders) || !text(times) || !text(r.failure) ||
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

// A worker: makes its context, then reads job indices and answers each
// with its phases and its result (batch_worker.h).
[[noreturn]] void workerMain(int jobsFd, int resultsFd, const std::vector<BatchJob>& jobs, const BatchSettings& s) {
    // Made before the first job is read, so a job's time is its own.
    std::unique_ptr<GlContext> context;
    std::string contextError;
    BackendChoice choice;
    stickIfAsked();
    if (parseBackend(s.backend, choice)) context = createContext(choice, contextError);
    else contextError = "unknown backend '" + s.backend + "'";
    bool open = true;
    auto send = [&](WorkerMessage m, const std::string& bytes) {
        m.length = std::uint32_t(bytes.size());
        open = open && writeAll(resultsFd, &m, sizeof m) && writeAll(resultsFd, bytes.data(), bytes.size());
    };
    std::uint32_t index = 0;
    while (open && readAll(jobsFd, &index, sizeof index)) {
        if (index >= jobs.size()) break;
        send({WorkerMessage::Phase, index, kPhasePreparing, 0}, "");
        BatchResult r;
        try {
            r = renderOne(jobs[index], s, context.get(), contextError,
                          [&](int setting) { send({WorkerMessage::Phase, index, setting, 0}, ""); });
        } catch (const std::exception& e) {
            r.exitCode = 1;
            r.diagnostics = std::string("glimmer: error: ") + e.what() + "\n";
            r.json = failedResultJson(jobs[index], r.diagnostics);
        }
        send({WorkerMessage::Result, index, r.exitCode, 0}, encodeResult(r));
        // A context that failed once is not trusted with another script.
        if (!r.failure.empty()) break;
    }
    std::fflush(nullptr);
    ::_exit(0);
}

double contextLimitSeconds(const BatchSettings& s) {
    const std::optional<TestFault> f = testFaultAsked();
    return f && f->kind == "stuck" ? 2 : s.contextSeconds;
}

std::string failedResultJson(const BatchJob& job, const std::string& diagnostics) {
    return resultJson(job, 1, diagnostics, "", 0, 0, 0, "unchecked");
}

}  // namespace glimmer
