// The options a grader uses on untrusted scripts (docs/RELIABILITY.md):
// --sandbox, --max-memory and --timeout, shared by render, check and sheet.
#include <CLI/CLI.hpp>

#include "app/subcommands.h"

namespace glimmer {

void addSafetyOptions(CLI::App* sub, CommonOptions& o) {
    sub->add_flag("--sandbox", o.sandbox, "read only files inside the script's folder and -I folders");
    sub->add_option("--max-memory", o.maxMemoryMiB, "MiB that textures and render targets may take together "
                                                    "(default 2048)")
        ->check(CLI::Range(std::uint64_t(1), std::uint64_t(1) << 20));
    sub->add_option("--timeout", o.timeoutSeconds, "SECONDS: stop the drawing after this long and name the pass "
                                                   "that was drawing (exit 1); default: no limit")
        ->check(CLI::Range(0.001, 86400.0));
}

}  // namespace glimmer
