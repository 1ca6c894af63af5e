#include "view/panel_watch.h"

#include <imgui.h>

#include <cstring>

#include <fmt/format.h>

namespace glimmer {

namespace {

// Where the last item drawn is, under `name`, for tests that click it.
void remember(ViewerState& s, const char* name) {
    const ImVec2 at = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
    s.controlRects[name] = {at.x, at.y, size.x, size.y};
}

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
    ImGui::SetNextItemWidth(em * 14);
    bool enter = ImGui::InputTextWithHint("##watch", "watch: bloom.frag:12 rgbblur", field, sizeof field,
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    remember(s, "Watch");
    ImGui::SameLine();
    const bool watch = ImGui::Button("Watch");
    remember(s, "Watch button");
    if (watch || enter) asked.push_back(watchCommand(field));
    if (s.watch) {
        ImGui::SameLine();
        if (ImGui::Button("Stop")) asked.push_back(watchCommand("off"));
        remember(s, "Stop");
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
    remember(s, "Watch range");
    ImGui::SameLine();
    if (ImGui::Button("Fix range") && range[0] < range[1])
        asked.push_back(watchCommand(fmt::format("{},{}", range[0], range[1]), true));
    remember(s, "Fix range");
    ImGui::SameLine();
    if (ImGui::Button("Own range")) asked.push_back(watchCommand("auto", true));
    remember(s, "Own range");
    // The marker colours, so a checker in the picture can be read.
    for (const WatchMarker& m : kWatchMarkers) {
        ImGui::ColorButton(m.name, ImVec4(m.r / 255.f, m.g / 255.f, m.b / 255.f, 1.f), ImGuiColorEditFlags_NoTooltip,
                           ImVec2(em * 0.8f, em * 0.8f));
        ImGui::SameLine(0, em * 0.25f);
        ImGui::TextDisabled("%s", m.name);
        if (&m != &kWatchMarkers[2] && &m != &kWatchMarkers[5]) ImGui::SameLine();
    }
}

}  // namespace glimmer
