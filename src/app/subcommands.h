// The subcommands of the glimmer program: CLI11 wiring and one run function
// each, returning the process's exit code (pipeline/options.h).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/options.h"

namespace CLI {
class App;
class Option;
}

namespace glimmer {

void addRenderCommand(CLI::App& app, RenderOptions& options);
void addTradeoffCommand(CLI::App& app, TradeoffOptions& options);
int runTradeoff(const TradeoffOptions& options);
void addSheetCommand(CLI::App& app, SheetOptions& options);
int runSheet(const SheetOptions& options);
void addCheckCommand(CLI::App& app, CheckOptions& options);
struct ViewOptions;
void addViewCommand(CLI::App& app, ViewOptions& options);
int runRender(const RenderOptions& options);
// render --watch (app/watch_render.cpp): its options checked before the
// script is opened, then run on the opened session.
std::optional<int> checkWatchOptions(const RenderOptions& options);
struct Session;
int runRenderWatch(const RenderOptions& options, Session& session);
// --watch's text, parsed and set up on the session (render and check): an
// exit code, with the message printed, when it cannot be watched.
struct Watch;
std::optional<int> startWatchOption(const std::string& text, Session& session, Watch& watch);
void addBatchCommand(CLI::App& app, BatchOptions& options);
int runBatch(const BatchOptions& options);
void addBatchMergeCommand(CLI::App& app, BatchMergeOptions& options);
int runBatchMerge(const BatchMergeOptions& options);
int runCheck(const CheckOptions& options);

// glimmer serve (app/serve_command.cpp; the work in src/serve).
struct ServeOptions {
    std::string lessonDir, solution, roster, host = "0.0.0.0", publicAddress, pageDir, overrides;
    std::string stateDir = "glimmer-serve-state";
    int port = 8080;
    int jobs = 2;
};
void addServeCommand(CLI::App& app, ServeOptions& options);
int runServe(const ServeOptions& options);

// --backend with its choices, checked as it is read: every subcommand that
// makes a context refuses an unknown one with the same message (app/cli_options.cpp).
CLI::Option* addBackendOption(CLI::App* sub, std::string& backend);

// --sandbox and --max-memory (app/safety_options.cpp).
void addSafetyOptions(CLI::App* sub, CommonOptions& options);

}  // namespace glimmer
