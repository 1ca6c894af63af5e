// The Dear ImGui panel: a group of controls per Program, as glman had, plus
// the viewer's own buttons and readouts.
#include <fmt/format.h>
#include <imgui.h>

#include "plan/limits.h"
#include "view/viewer.h"

namespace glimmer {
namespace {

bool isIntType(const Renderer& r, int program, const std::string& name) {
    return r.uniformKind(program, name) == Renderer::UniformKind::Int;
}

std::string valuesText(const std::vector<double>& v) {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : " ") + fmt::format("{:g}", x);
    return s;
}

// One Program's controls. Returns true when a value changed.
void programGroup(ViewerState& s, int p, bool firstOpen) {
    const ProgramDecl& decl = s.good->plan.programs[size_t(p)];
    ImGui::PushID(p);
    if (ImGui::CollapsingHeader(decl.name.c_str(), firstOpen ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
        for (const auto& u : decl.uniforms) {
            std::vector<double> v = s.values->get(p, u.name);
            if (v.empty()) continue;
            bool changed = false;
            switch (u.form) {
            case UniformSetting::Form::Range:
                if (isIntType(*s.renderer, p, u.name)) {
                    int i = clampToInt(v[0]);
                    changed = ImGui::SliderInt(u.name.c_str(), &i, clampToInt(u.min), clampToInt(u.max));
                    v[0] = i;
                } else {
                    float f = float(v[0]);
                    changed = ImGui::SliderFloat(u.name.c_str(), &f, float(u.min), float(u.max));
                    v[0] = f;
                }
                break;
            case UniformSetting::Form::Bool: {
                bool b = v[0] != 0;
                changed = ImGui::Checkbox(u.name.c_str(), &b);
                v[0] = b ? 1 : 0;
                break;
            }
            case UniformSetting::Form::Color: {
                float c[4] = {float(v[0]), float(v[1]), float(v[2]), float(v[3])};
                changed = ImGui::ColorEdit4(u.name.c_str(), c);
                v = {c[0], c[1], c[2], c[3]};
                break;
            }
            case UniformSetting::Form::Array:
            case UniformSetting::Form::Constant:
                ImGui::TextDisabled("%s = %s", u.name.c_str(), valuesText(v).c_str());
                break;
            }
            if (changed) s.values->set(p, u.name, v);
        }
        if (ImGui::Button("Reset")) {
            for (const auto& u : decl.uniforms) s.values->set(p, u.name, u.values);
        }
    }
    ImGui::PopID();
}

}  // namespace

std::string overlayText(const ViewerState& s) {
    if (!s.good || !s.values) return {};
    std::string text;
    for (size_t p = 0; p < s.good->plan.programs.size(); ++p)
        for (const auto& u : s.good->plan.programs[p].uniforms)
            if (u.form == UniformSetting::Form::Range || u.form == UniformSetting::Form::Bool ||
                u.form == UniformSetting::Form::Color)
                text += fmt::format("{}{} = {}", text.empty() ? "" : "\n", u.name, valuesText(s.values->get(int(p), u.name)));
    return text;
}

std::vector<ViewCommand> drawPanel(ViewerState& s) {
    std::vector<ViewCommand> asked;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Glimmer");
    if (s.good) ImGui::TextUnformatted(s.good->plan.scriptFile.c_str());
    if (!s.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.45f, 0.4f, 1.f));
        ImGui::TextWrapped("%s", s.error.c_str());
        ImGui::PopStyleColor();
        ImGui::TextDisabled("showing the last picture that worked");
    }
    auto command = [](ViewCommand::Kind kind, std::string file = {}) {
        ViewCommand c;
        c.kind = kind;
        c.name = std::move(file);
        return c;
    };
    if (ImGui::Button("Reload")) asked.push_back(command(ViewCommand::Kind::Reload));
    ImGui::SameLine();
    if (ImGui::Button("Save PNG (S)")) asked.push_back(command(ViewCommand::Kind::Save, "glimmer.png"));
    ImGui::SameLine();
    ImGui::Checkbox("Show values", &s.showValues);
    ImGui::InputInt2("size", s.hardcopy);
    ImGui::SameLine();
    if (ImGui::Button("Save at size")) {
        ViewCommand c = command(ViewCommand::Kind::Save, "glimmer-hardcopy.png");
        c.unit = -2;  // marks a hardcopy at s.hardcopy
        asked.push_back(c);
    }
    if (ImGui::Button(s.playing ? "Pause" : "Play")) s.playing = !s.playing;
    ImGui::SameLine();
    if (ImGui::Button("Step")) {
        s.playing = false;
        s.time += 1.0 / 30.0;
    }
    ImGui::SameLine();
    ImGui::Text("t = %.2f s", s.time);
    if (ImGui::Button("Reset view")) {
        s.yaw = s.pitch = 0;
        s.zoom = 1;
        s.sceneMoved = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("drag: rotate, wheel: zoom");

    if (s.good) {
        // The pass inspector: any render target full-window.
        std::string current = s.shownTexture < 0 ? "screen" : fmt::format("texture {}", s.shownTexture);
        if (ImGui::BeginCombo("show", current.c_str())) {
            if (ImGui::Selectable("screen", s.shownTexture < 0)) s.shownTexture = -1;
            for (const auto& [unit, tex] : s.good->plan.finalUnits) {
                if (!s.good->plan.textures[size_t(tex)].renderTarget) continue;
                std::string label = fmt::format("unit {} (target)", unit);
                if (ImGui::Selectable(label.c_str(), s.shownTexture == tex)) s.shownTexture = tex;
            }
            ImGui::EndCombo();
        }
        ImGui::Text("frame %.1f ms", s.lastFrameMs);
        for (const auto& t : s.lastTimings) {
            const Pass& pass = s.good->plan.passes[size_t(t.pass)];
            ImGui::Text("  pass %d (line %d, %s): %.2f ms", t.pass, pass.loc.line,
                        pass.targets.empty() ? "screen" : "target", t.ms);
        }
        // A warning badge for any target holding NaN, Inf, negatives or
        // values past the half-float range (see render --health).
        for (const auto& h : s.health) {
            if (!h.bad()) continue;
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.75f, 0.2f, 1.f));
            ImGui::TextWrapped("(!) %s: %zu NaN, %zu Inf, %zu negative, %zu above 65504", h.name.c_str(), h.health.nan,
                               h.health.inf, h.health.negative, h.health.above65504);
            ImGui::PopStyleColor();
        }
        for (size_t p = 0; p < s.good->plan.programs.size(); ++p) programGroup(s, int(p), p == 0);
    }
    if (!s.status.empty()) ImGui::TextDisabled("%s", s.status.c_str());
    ImGui::End();
    return asked;
}

}  // namespace glimmer
