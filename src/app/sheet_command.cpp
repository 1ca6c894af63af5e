// glimmer sheet: a labelled grid of renders for a handout, such as the seed
// slide's uAdd = 0 / 2 / 4 row, in one command. One context and one
// renderer serve every cell, and each cell re-runs only the passes its
// change reaches (varying uAdd leaves the superblur as it is).
#include <filesystem>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands.h"
#include "driver/session.h"
#include "app/sheet_layout.h"
#include "driver/console.h"
#include "plan/dependencies.h"

namespace glimmer {
namespace {

struct Axis {
    std::string name;
    std::vector<std::string> values;
};

bool parseVary(const std::string& text, Axis& a) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 >= text.size()) return false;
    a.name = text.substr(0, eq);
    std::stringstream ss(text.substr(eq + 1));
    for (std::string v; std::getline(ss, v, ',');)
        if (!v.empty()) a.values.push_back(v);
    return !a.values.empty();
}

void blit(Image& sheet, const Image& cell, int x0, int y0) {
    for (int y = 0; y < cell.height && y0 + y < sheet.height; ++y)
        std::copy_n(&cell.u8[size_t(y) * size_t(cell.width) * 4], size_t(cell.width) * 4,
                    &sheet.u8[(size_t(y0 + y) * size_t(sheet.width) + size_t(x0)) * 4]);
}

}  // namespace

void addSheetCommand(CLI::App& app, SheetOptions& o) {
    CLI::App* sub = app.add_subcommand("sheet", "render a labelled grid of a script at several uniform values");
    sub->add_option("script", o.script, "the .glib script")->required();
    sub->add_option("--vary", o.vary, "NAME=V1,V2,...: columns; a second --vary gives rows")->required();
    sub->add_option("-o,--output", o.output, "the PNG to write");
    sub->add_option("--size", o.size, "size of each cell WxH (default 256x256)");
    sub->add_option("--set", o.sets, "NAME=VALUE for the uniforms that do not vary: a number, true/false, R,G,B[,A] or X,Y,... (repeatable)");
    sub->add_option("--backend", o.backend, "auto, osmesa, egl, egl-device, egl-surfaceless or egl-gles (OpenGL ES 3.0: WebGL 2's level)");
    sub->add_option("-I,--include", o.includeDirs, "another folder to find shaders and images in");
    addSafetyOptions(sub, o);
}

int runSheet(const SheetOptions& o) {
    std::vector<Axis> axes;
    for (const auto& v : o.vary) {
        Axis a;
        if (!parseVary(v, a)) {
            std::cerr << fmt::format("glimmer: error: --vary '{}' is not NAME=V1,V2,...\n", v);
            return kExitUsage;
        }
        axes.push_back(a);
    }
    if (axes.size() > 2) {
        std::cerr << "glimmer: error: --vary can be given at most twice (columns, then rows)\n";
        return kExitUsage;
    }
    CommonOptions common = o;
    if (common.size.empty()) common.size = "256x256";
    Session s;
    if (auto code = openSession(common, {}, false, s)) return *code;
    const Plan& plan = s.loaded.plan;

    // Every value must be valid before anything is drawn.
    Axis none{"", {""}};
    const Axis& cols = axes[0];
    const Axis& rows = axes.size() > 1 ? axes[1] : none;
    for (const Axis* a : {&cols, &rows}) {
        for (const auto& v : a->values) {
            if (a->name.empty()) continue;
            Diagnostics d;
            UniformValues probe = *s.values;
            if (!probe.applySet(plan, a->name + "=" + v, d, "--vary") || d.warningCount() > 0) {
                printDiagnostics(d, s.loaded.sources, std::cerr);
                return kExitUsage;
            }
        }
    }

    std::vector<std::string> colValues = cols.values, rowValues;
    if (!rows.name.empty()) rowValues = rows.values;
    std::string title = std::filesystem::path(o.script == "-" ? kStdinScriptName : o.script).filename().string();
    for (const auto& set : o.sets) {
        auto eq = set.find('=');
        title += "   " + set.substr(0, eq) + " = " + set.substr(eq + 1);
    }
    SheetLayout layout = layoutSheet(title, cols.name, colValues, rows.name, rowValues, plan.width, plan.height);
    Image sheet = Image::rgba8(layout.width, layout.height);
    for (size_t i = 0; i < sheet.u8.size(); ++i) sheet.u8[i] = (i % 4 == 3) ? 255 : 24;
    drawSheetLabels(sheet, layout);

    UniformValues drawn = *s.values;
    bool first = true;
    int done = 0, total = int(cols.values.size() * rows.values.size());
    Progress progress;
    for (size_t r = 0; r < rows.values.size(); ++r) {
        for (size_t c = 0; c < cols.values.size(); ++c) {
            UniformValues v = *s.values;
            Diagnostics d;
            v.applySet(plan, cols.name + "=" + cols.values[c], d, "--vary");
            if (!rows.name.empty()) v.applySet(plan, rows.name + "=" + rows.values[r], d, "--vary");
            Change change;
            change.everything = first;
            change.programs = v.programsDifferingFrom(drawn);
            std::vector<bool> only = passesToRun(plan, change);
            s.renderer->render(v, 0, nullptr, &only);
            drawn = v;
            first = false;
            auto [x, y] = layout.cellOrigin(int(c), int(r));
            blit(sheet, s.renderer->readScreen(), x, y);
            progress.update(fmt::format("sheet: {}/{} rendered", ++done, total));
        }
    }
    progress.finish();
    std::string why;
    if (!writePng(o.output, sheet, why)) {
        std::cerr << "glimmer: error: " << why << "\n";
        return kExitScriptError;
    }
    reportWrote(fmt::format("{} ({} by {} cells of {}x{}, {}x{})", o.output, cols.values.size(), rows.values.size(),
                            plan.width, plan.height, sheet.width, sheet.height));
    return kExitOk;
}

}  // namespace glimmer
