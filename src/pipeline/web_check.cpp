#include "pipeline/web_check.h"

#include <iostream>

#include <fmt/format.h>

#include "pipeline/prepare_script.h"
#include "gl/shader_build.h"
#include "plan/inputs.h"
#include "plan/uniform_values.h"
#include "shader/translation_cache.h"
#include "shader/web_stage.h"

namespace glimmer {

bool checkProgramsForWeb(const LoadedScript& script, Diagnostics& diags) {
    const int errorsBefore = diags.errorCount();
    const Plan& plan = script.plan;
    for (size_t i = 0; i < plan.programs.size(); ++i) {
        const ProgramDecl& decl = plan.programs[i];
        // A stage WebGL 2 lacks: one message at the Program, not one per
        // stage, and nothing translated (the program could never link there).
        const ShaderStage* refused = nullptr;
        for (const ShaderStage& stage : decl.stages)
            if (!refused && !webRefusal(webStage(stage.kind)).empty()) refused = &stage;
        if (refused) {
            diags.error(plan.scriptFile, decl.loc,
                        fmt::format("Program {} cannot run in WebGL 2: its {} '{}' cannot be translated; {}", decl.name,
                                    webStageName(webStage(refused->kind)), refused->shown,
                                    webRefusal(webStage(refused->kind))));
            continue;
        }
        const auto& texts = i < script.assets.shaderTexts.size() ? script.assets.shaderTexts[i]
                                                                 : std::vector<std::optional<std::string>>{};
        for (size_t k = 0; k < decl.stages.size(); ++k) {
            if (k >= texts.size() || !texts[k]) continue;  // unreadable: the load step said so
            WebTranslateInput in;
            in.text = *texts[k];
            in.stage = webStage(decl.stages[k].kind);
            in.file = decl.stages[k].path;
            in.prelude = decl.gstap ? kGstapPrelude : "";
            translateForWebCached(in, diags);
        }
    }
    return diags.errorCount() == errorsBefore;
}

int runWebCheck(const CommonOptions& o, std::ostream* inputs) {
    Diagnostics diags;
    LoadedScript loaded;
    PlanOptions planOptions;
    planOptions.includeDirs = o.includeDirs;
    planOptions.standIns = o.standIns;
    planOptions.sandbox = o.sandbox;
    if (o.maxMemoryMiB > 0) planOptions.maxMemoryBytes = o.maxMemoryMiB << 20;
    if (!o.size.empty() && !parseSize(o.size, planOptions.width, planOptions.height)) {
        std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT (1 to 16384 each)\n", o.size);
        return kExitUsage;
    }
    if (!loadScript(o.script, planOptions, diags, loaded)) {
        printDiagnostics(diags, loaded.sources, std::cerr);
        return kExitUsage;
    }
    if (diags.hasErrors()) {
        printDiagnostics(diags, loaded.sources, std::cerr);
        return kExitScriptError;
    }
    // --set is checked as `check` checks it: a name no Program sets is a usage error.
    UniformValues values(loaded.plan);
    Diagnostics setDiags;
    bool setsOk = true;
    for (const auto& a : o.sets) setsOk &= values.applySet(loaded.plan, a, setDiags);
    for (const auto& d : setDiags.all()) diags.add(d);
    if (!setsOk) {
        printDiagnostics(diags, loaded.sources, std::cerr);
        return kExitUsage;
    }
    bool filesOk = loadFiles(loaded, true, diags);
    bool translated = checkProgramsForWeb(loaded, diags);
    printDiagnostics(diags, loaded.sources, std::cerr);
    if (!filesOk || !translated) return kExitScriptError;
    if (inputs)
        for (const PlanInput& in : inputsOf(loaded.plan)) *inputs << in.path << "\n";
    return kExitOk;
}

}  // namespace glimmer
