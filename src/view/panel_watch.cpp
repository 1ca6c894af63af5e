#include "view/panel_watch.h"
#include "view/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

namespace glimmer {

namespace {

ViewCommand watchCommand(std::string text, bool range = false) {
    ViewCommand c;
    c.kind = ViewCommand::Kind::Watch;
    c.text = std::move(text);
    if (range) c.name = "range";
    return c;
}

}  // namespace

void watchControls(ViewerState& s, std::vector<ViewCommand>& asked) {
    // The field keeps what is typed between frames; a watch asked for
    // elsewhere (a command, the page's editor) shows up in it.
    static char field[kMaxWatchExpression + 64] = "";
    static std::string shown;
    if (shown != s.watchSpec && !ImGui::IsAnyItemActive()) {
        std::snprintf(field, sizeof field, "%s", s.watchSpec.c_str());
        shown = s.watchSpec;
    }
    const float em = ImGui::GetFontSize();
    // The field takes what the row has left beside its buttons (14 em at
    // most), so Watch and Stop are never cut at the panel's edge.
    const ImGuiStyle& style = ImGui::GetStyle();
    auto buttonW = [&](const char* label) { return ImGui::CalcTextSize(label).x + style.FramePadding.x * 2 + style.ItemSpacing.x; };
    const float buttons = buttonW("Watch") + (s.watch ? buttonW("Stop") : 0.f);
    const float fieldW = std::clamp(ImGui::GetContentRegionAvail().x - buttons, em * 6, em * 14);
    ImGui::SetNextItemWidth(fieldW);
    bool enter = ImGui::InputTextWithHint("##watch", "watch: bloom.frag:12 rgbblur", field, sizeof field,
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    rememberControl(s, "Watch", fieldW);
    ImGui::SameLine();
    const bool watch = ImGui::Button("Watch");
    rememberControl(s, "Watch button");
    if (watch || enter) asked.push_back(watchCommand(field));
    if (s.watch) {
        ImGui::SameLine();
        if (ImGui::Button("Stop")) asked.push_back(watchCommand("off"));
        rememberControl(s, "Stop");
    }
    // Idle, the field is all (its hint says what to type): one line of the
    // panel, so the sliders stay where the projector shows them.
    if (!s.watch && s.watchError.empty()) return;
    if (!s.watchError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.45f, 0.4f, 1.f));
        ImGui::TextWrapped("%s", s.watchError.c_str());
        ImGui::PopStyleColor();
        return;
    }
    // The summary a part a line (type and range; each component; each count),
    // so a narrow panel cuts none of it off.
    for (size_t at = 0; at <= s.watchSummary.size();) {
        size_t end = s.watchSummary.find("; ", at);
        if (end == std::string::npos) end = s.watchSummary.size();
        ImGui::TextWrapped("%s", s.watchSummary.substr(at, end - at).c_str());
        at = end + 2;
    }
    // A fixed range, or the values' own.
    static float range[2] = {0.f, 1.f};
    ImGui::SetNextItemWidth(em * 8);
    ImGui::InputFloat2("##range", range, "%.3g");
    rememberControl(s, "Watch range", em * 8);
    ImGui::SameLine();
    if (ImGui::Button("Fix range") && range[0] < range[1])
        asked.push_back(watchCommand(fmt::format("{},{}", range[0], range[1]), true));
    rememberControl(s, "Fix range");
    ImGui::SameLine();
    if (ImGui::Button("Own range")) asked.push_back(watchCommand("auto", true));
    rememberControl(s, "Own range");
    // The marker colours, so a checker in the picture can be read.
    // As many to a row as the panel's width holds: none cut at its edge.
    const float room = ImGui::GetContentRegionAvail().x;
    float used = 0;
    for (const WatchMarker& m : kWatchMarkers) {
        const float w = em * 1.05f + ImGui::CalcTextSize(m.name).x;
        if (used > 0 && used + style.ItemSpacing.x + w <= room) {
            ImGui::SameLine();
            used += style.ItemSpacing.x + w;
        } else {
            used = w;
        }
        ImGui::ColorButton(m.name, ImVec4(m.r / 255.f, m.g / 255.f, m.b / 255.f, 1.f), ImGuiColorEditFlags_NoTooltip,
                           ImVec2(em * 0.8f, em * 0.8f));
        ImGui::SameLine(0, em * 0.25f);
        ImGui::TextDisabled("%s", m.name);
    }
}

}  // namespace glimmer
