#include "process/session.h"

#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "pipeline/prepare_script.h"
#include "process/watchdog.h"
#include "pipeline/script_checks.h"

namespace glimmer {

std::optional<int> openSession(const CommonOptions& options, const std::set<int>& keepUnits, bool everything,
                               Session& s) {
    using Clock = std::chrono::steady_clock;
    Diagnostics diags;
    ScriptRequest request;
    request.script = options.script;
    request.everything = everything;
    PlanOptions& planOptions = request.plan;
    planOptions.includeDirs = options.includeDirs;
    planOptions.standIns = options.standIns;
    planOptions.sandbox = options.sandbox;
    if (options.maxMemoryMiB > 0) planOptions.maxMemoryBytes = options.maxMemoryMiB << 20;
    planOptions.keepTargets = keepUnits;
    if (!options.size.empty() && !parseSize(options.size, planOptions.width, planOptions.height)) {
        std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT (1 to 16384 each)\n", options.size);
        return kExitUsage;
    }
    BackendChoice backend;
    if (!parseBackend(options.backend, backend)) {
        std::cerr << fmt::format("glimmer: error: unknown backend '{}'\n", options.backend);
        return kExitUsage;
    }
    if (!loadScript(request.script, planOptions, diags, s.loaded)) {
        printDiagnostics(diags, s.loaded.sources, std::cerr);
        return kExitUsage;
    }
    if (!diags.hasErrors()) warnIfDrawsNothing(s.loaded.plan, diags);
    // --set is checked before any GL work: a typo should not cost a compile.
    s.values.emplace(s.loaded.plan);
    Diagnostics setDiags;
    bool setsOk = true;
    for (const auto& a : options.sets) setsOk &= s.values->applySet(s.loaded.plan, a, setDiags);
    // One list, so that the summary line counts everything printed above it.
    bool scriptOk = !diags.hasErrors();
    for (const auto& d : setDiags.all()) diags.add(d);
    if (!scriptOk || !setsOk) {
        printDiagnostics(diags, s.loaded.sources, std::cerr);
        return scriptOk ? kExitUsage : kExitScriptError;
    }

    // Files are read before a context is made: a missing image costs no driver start-up.
    auto l0 = Clock::now();
    bool filesOk = loadFiles(s.loaded, everything, diags);
    auto t0 = Clock::now();
    std::string why;
    s.context = createContext(backend, why);
    if (!s.context) {
        printDiagnostics(diags, s.loaded.sources, std::cerr);
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    s.renderer = Renderer::create([&](const char* n) { return s.context->getProcAddress(n); }, why);
    if (!s.renderer) {
        printDiagnostics(diags, s.loaded.sources, std::cerr);
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    auto t1 = Clock::now();
    bool ok = uploadScript(*s.renderer, s.loaded, everything, diags) && filesOk;
    auto t2 = Clock::now();
    s.startupMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
    s.compileMs = std::chrono::duration<double, std::milli>((t2 - t1) + (t0 - l0)).count();
    printDiagnostics(diags, s.loaded.sources, std::cerr);
    if (!ok) return kExitScriptError;
    if (passesWatched()) {  // --timeout: tell the watchdog which pass draws
        const Plan* plan = &s.loaded.plan;
        s.renderer->setPassListener([plan](int pass) { reportPassStart(plan->passes[size_t(pass)].loc); });
    }
    return std::nullopt;
}

}  // namespace glimmer
