// glimmer sheet: a labelled grid of renders for a handout, such as the seed
// slide's uAdd = 0 / 2 / 4 row, in one command. One context and one
// renderer serve every cell (sheet/sheet_drawing.h).
#include <filesystem>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/subcommands.h"
#include "process/output_guard.h"
#include "process/session.h"
#include "sheet/sheet_request.h"
#include "pipeline/console.h"

namespace glimmer {

void addSheetCommand(CLI::App& app, SheetOptions& o) {
    CLI::App* sub = app.add_subcommand("sheet", "render a labelled grid of a script at several uniform values");
    sub->add_option("script", o.script, "the .glib script")->required();
    sub->add_option("--vary", o.vary, "NAME=V1,V2,...: columns; a second --vary gives rows")->required();
    sub->add_option("-o,--output", o.output, "the PNG to write");
    sub->add_option("--size", o.size, "size of each cell WxH (default 256x256)");
    sub->add_option("--set", o.sets, "NAME=VALUE for the uniforms that do not vary: a number, true/false, R,G,B[,A] or X,Y,... (repeatable)");
    addBackendOption(sub, o.backend);
    sub->add_option("-I,--include", o.includeDirs, "another folder to find shaders and images in");
    addSafetyOptions(sub, o);
}

int runSheet(const SheetOptions& o) {
    // The axes' form first: a usage error needs no context.
    for (const auto& v : o.vary)
        if (SheetAxis a; !parseSheetAxis(v, a)) {
            std::cerr << fmt::format("glimmer: error: --vary '{}' is not NAME=V1,V2,...\n", v);
            return kExitUsage;
        }
    CommonOptions common = o;
    if (common.size.empty()) common.size = "256x256";
    Session s;
    if (auto code = openSession(common, {}, false, s)) return *code;
    const Plan& plan = s.loaded.plan;
    if (std::string refusal = overwritesAnInput(plan, "-o", o.output, "sheet"); !refusal.empty()) {  // process/output_guard.h
        std::cerr << refusal;
        return kExitUsage;
    }
    // Every value must be valid before anything is drawn (sheet/sheet_request.h, as the page's Save sheet).
    SheetRequest request;
    std::string usage;
    Diagnostics d;
    const std::string scriptName = std::filesystem::path(o.script == "-" ? kStdinScriptName : o.script).filename().string();
    if (!makeSheetRequest(o.vary, scriptName, plan, *s.values, request, usage, d)) {
        if (!usage.empty()) std::cerr << "glimmer: error: " << usage << "\n";
        printDiagnostics(d, s.loaded.sources, std::cerr);
        return kExitUsage;
    }
    const SheetAxis& cols = request.cols;
    const SheetAxis& rows = request.rows;
    Progress progress;
    Image sheet = drawSheet(*s.renderer, plan, *s.values, cols, rows, request.title, [&](int done, int total) {
        progress.update(fmt::format("sheet: {}/{} rendered", done, total));
    });
    progress.finish();
    std::string why;
    if (!writePng(o.output, sheet, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    reportWrote(fmt::format("{} ({} by {} cells of {}x{}, {}x{})", o.output, cols.values.size(),
                            rows.name.empty() ? size_t(1) : rows.values.size(),
                            plan.width, plan.height, sheet.width, sheet.height));
    return kExitOk;
}

}  // namespace glimmer
