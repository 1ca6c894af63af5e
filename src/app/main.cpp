// glimmer: run GLIB scripts. `glimmer render` draws a script headless to a
// PNG; `glimmer check` finds every problem without drawing; `glimmer view`
// (or plain `glimmer script.glib`) opens the live window.
#include <csignal>
#include <functional>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/subcommands.h"
#include "process/child_guard.h"
#include "process/watchdog.h"
#include "app/help_text.h"
#include "lang/diagnostics.h"
#include "view/viewer.h"

namespace {

int run(int argc, char** argv) {
    using namespace glimmer;
    CLI::App app{"Glimmer: a GLIB-style scripted shader playground"};
    app.require_subcommand(1);
    GlobalOptions globals;
    addGlobalOptions(app, globals);
    RenderOptions render;
    CheckOptions check;
    ViewOptions view;
    SheetOptions sheet;
    TradeoffOptions tradeoff;
    BatchOptions batch;
    BatchMergeOptions batchMerge;
    ServeOptions serve;
    addRenderCommand(app, render);
    addCheckCommand(app, check);
    addViewCommand(app, view);
    addSheetCommand(app, sheet);
    addTradeoffCommand(app, tradeoff);
    addBatchCommand(app, batch);
    addBatchMergeCommand(app, batchMerge);
    addServeCommand(app, serve);
    // `glimmer script.glib` is `glimmer view script.glib`, as glslViewer.
    std::vector<char*> args(argv, argv + argc);
    std::string viewWord = "view";
    auto endsWith = [](const std::string& s, const std::string& e) {
        return s.size() >= e.size() && s.compare(s.size() - e.size(), e.size(), e) == 0;
    };
    if (argc > 1 && endsWith(argv[1], ".glib")) args.insert(args.begin() + 1, viewWord.data());
    if (auto code = runHelp(app, std::vector<std::string>(args.begin(), args.end()))) return *code;
    // CLI11 reports a mistyped command as "A subcommand is required"; name it.
    std::string first = args.size() > 1 ? args[1] : "";
    if (!first.empty() && first[0] != '-' && first != "render" && first != "check" && first != "view" &&
        first != "sheet" && first != "tradeoff" && first != "batch" && first != "batch-merge" &&
        first != "serve") {
        std::cerr << "glimmer: error: unknown command '" << first
                  << "'; the commands are 'render', 'check', 'view', 'sheet', 'tradeoff', 'batch', 'batch-merge' and 'serve'\n"
                  << "Run with --help for more information.\n";
        return kExitUsage;
    }
    try {
        app.parse(int(args.size()), args.data());
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? kExitOk : kExitUsage;
    }
    if (auto code = applyGlobalOptions(globals)) return *code;
    // Under --sandbox the script is untrusted: its GL work runs in a child
    // whose address space is bounded (process/child_guard.h).
    auto guarded = [](const CommonOptions& o, const std::function<int()>& work) {
        return runWithTimeout(o.timeoutSeconds, o.script, work,
                              o.sandbox ? sandboxAddressSpaceBytes(o.maxMemoryMiB) : 0);
    };
    if (app.got_subcommand("render")) return guarded(render, [&] { return runRender(render); });
    if (app.got_subcommand("check")) return guarded(check, [&] { return runCheck(check); });
    if (app.got_subcommand("view")) return runView(view);
    if (app.got_subcommand("sheet")) return guarded(sheet, [&] { return runSheet(sheet); });
    if (app.got_subcommand("tradeoff")) return runTradeoff(tradeoff);
    if (app.got_subcommand("batch")) return runBatch(batch);
    if (app.got_subcommand("batch-merge")) return runBatchMerge(batchMerge);
    if (app.got_subcommand("serve")) return runServe(serve);
    return kExitUsage;
}

}  // namespace

// Nothing a script does may abort the process (exit 134): whatever escapes a
// command is reported, and the exit code stays 1 (script) as documented.
int main(int argc, char** argv) {
    // A write past a file-size limit fails with EFBIG and is reported, as a
    // full disk is, instead of killing the process (util/write_file.h).
    std::signal(SIGXFSZ, SIG_IGN);
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "glimmer: error: out of memory (the script asks for more than this machine can give)\n";
    } catch (const std::exception& e) {
        std::cerr << "glimmer: error: " << glimmer::sanitizeForTerminal(e.what(), false) << "\n";
    } catch (...) {
        std::cerr << "glimmer: error: unexpected failure\n";
    }
    return glimmer::kExitScriptError;
}
