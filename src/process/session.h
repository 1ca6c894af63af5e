// A script loaded, planned and prepared on a GL context of its own: what
// `render`, `check` and `sheet` start from. The steps themselves are
// pipeline/prepare_script.h; this adds options, a context and printing.
// Every way it can fail is a message a user reads, one line each, and an
// exit code; the tests hold it to that where no context or no renderer can
// be made (issue 40's sampled mutants found the second untested: the CLI
// tests' stand-in driver, tests/stand_in_drivers/, is how it is reached).
#pragma once
#include <memory>
#include <optional>
#include <set>

#include "pipeline/load_script.h"
#include "pipeline/options.h"
#include "backends/context.h"
#include "gl/renderer.h"
#include "plan/uniform_values.h"

namespace glimmer {

struct Session {
    LoadedScript loaded;
    std::unique_ptr<GlContext> context;
    std::unique_ptr<Renderer> renderer;
    std::optional<UniformValues> values;
    double startupMs = 0, compileMs = 0;  // context + GL table; loading + compiling
};

// Runs every step up to a prepared renderer, printing diagnostics to stderr.
// Returns an exit code when it cannot go on, nullopt when the session is ready.
std::optional<int> openSession(const CommonOptions& options, const std::set<int>& keepUnits, bool everything,
                               Session& s);

}  // namespace glimmer
