// Vertex, Fragment, ... and Program: shader stages and the uniforms a
// Program line sets.
#include "plan/builder.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "plan/uniform_forms.h"

namespace glimmer {
namespace plan_detail {

void Builder::stage(const Command& c, ShaderStage::Kind kind) {
    stages_.erase(kind);
    missingStages_.erase(kind);
    if (c.args.empty()) return;  // no argument un-sets the stage
    if (c.args.size() != 1 || c.args[0].kind != Arg::Kind::Word) {
        diags_.error(file(), c.loc, fmt::format("{} takes one shader file name", c.spelled));
        return;
    }
    ShaderStage s;
    s.kind = kind;
    s.shown = c.args[0].text;
    s.loc = c.args[0].loc;
    bool usable = false;
    s.path = findFile(c.args[0], "shader", usable);
    if (!usable) {
        missingStages_.insert(kind);
        return;
    }
    stages_[kind] = s;
}

void Builder::program(const Command& c) {
    if (c.args.empty() || c.args[0].kind != Arg::Kind::Word) {
        diags_.error(file(), c.loc, "Program needs a name");
        return;
    }
    ProgramDecl p;
    p.name = c.args[0].text;
    p.loc = c.loc;
    p.gstap = gstap_;
    p.notes = std::move(pendingNotes_);
    pendingNotes_.clear();
    for (const auto& [kind, s] : stages_) p.stages.push_back(s);
    // A shader named but not found was reported where it was named; saying
    // here that the Program has none would be the same mistake twice.
    if (p.stages.empty() && missingStages_.empty())
        diags_.warning(file(), c.loc, fmt::format("Program {} has no shaders; set Vertex and Fragment first", p.name));
    p.uniforms = parseUniformSettings(c, 1, file(), diags_);
    bool fixedFunction = p.stages.empty();
    plan_.programs.push_back(std::move(p));
    // A Program without shaders draws with OpenGL's fixed function.
    program_ = fixedFunction ? -1 : int(plan_.programs.size()) - 1;
}

}  // namespace plan_detail

}  // namespace glimmer
