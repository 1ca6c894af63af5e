// What glimmer says about itself: --version, `glimmer help [COMMAND]`, the
// footer of --help, -q/-v, and the man page, all from the one CLI11 App so
// the man page and --help never disagree.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace glimmer {

struct GlobalOptions {
    bool quiet = false;
    bool verbose = false;
};

// The program's description, --version, -q/-v (accepted before or after the
// command), defaults shown in every --help, the `glimmer SCRIPT.glib`
// shortcut in the footer, and `help` in the list of commands. Call before
// adding the commands.
void addGlobalOptions(CLI::App& app, GlobalOptions& options);

// Sets the verbosity from -q/-v once parsed; a usage error when both are given.
std::optional<int> applyGlobalOptions(const GlobalOptions& options);

// `glimmer help [COMMAND]` and `glimmer --man`: the exit code when `args`
// (argv) is one of these, after printing; nullopt otherwise.
std::optional<int> runHelp(CLI::App& app, const std::vector<std::string>& args);

// The man page, roff, from the App's commands and options.
std::string manPage(CLI::App& app);

}  // namespace glimmer
