// glimmer: run GLIB scripts. `glimmer render` draws a script headless to a
// PNG; `glimmer check` finds every problem without drawing.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands.h"

int main(int argc, char** argv) {
    using namespace glimmer;
    CLI::App app{"Glimmer: a GLIB-style scripted shader playground"};
    app.require_subcommand(1);
    RenderOptions render;
    CommonOptions check;
    addRenderCommand(app, render);
    addCheckCommand(app, check);
    // CLI11 reports a mistyped command as "A subcommand is required"; name it.
    if (argc > 1 && argv[1][0] != '-' && std::string(argv[1]) != "render" && std::string(argv[1]) != "check") {
        std::cerr << "glimmer: error: unknown command '" << argv[1] << "'; the commands are 'render' and 'check'\n"
                  << "Run with --help for more information.\n";
        return kExitUsage;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? kExitOk : kExitUsage;
    }
    if (app.got_subcommand("render")) return runRender(render);
    if (app.got_subcommand("check")) return runCheck(check);
    return kExitUsage;
}
