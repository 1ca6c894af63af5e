#include "pipeline/prepare_script.h"

namespace glimmer {

bool planScript(const ScriptRequest& request, Diagnostics& diags, LoadedScript& out) {
    return loadScript(request.script, request.plan, diags, out) && !diags.hasErrors();
}

bool loadFiles(LoadedScript& script, bool everything, Diagnostics& diags) {
    return loadAssets(script.plan, everything, diags, script.sources, script.assets);
}

bool uploadScript(Renderer& renderer, LoadedScript& script, bool everything, Diagnostics& diags) {
    bool ok = renderer.prepare(script.plan, script.assets, diags, everything);
    script.assets = {};
    return ok;
}

bool loadAndUpload(Renderer& renderer, LoadedScript& script, bool everything, Diagnostics& diags) {
    bool filesOk = loadFiles(script, everything, diags);
    return uploadScript(renderer, script, everything, diags) && filesOk;
}

std::unique_ptr<Renderer> prepareScript(const ScriptRequest& request, const GetProcAddress& getProc,
                                        Diagnostics& diags, LoadedScript& out) {
    if (!planScript(request, diags, out)) return nullptr;
    bool filesOk = loadFiles(out, request.everything, diags);
    std::string why;
    auto renderer = Renderer::create(getProc, why);
    if (!renderer) {
        diags.error(request.script, {}, why);
        return nullptr;
    }
    bool uploaded = uploadScript(*renderer, out, request.everything, diags);
    return filesOk && uploaded ? std::move(renderer) : nullptr;
}

bool prepareScript(const ScriptRequest& request, Renderer& renderer, Diagnostics& diags, LoadedScript& out) {
    return planScript(request, diags, out) && loadAndUpload(renderer, out, request.everything, diags);
}

}  // namespace glimmer
