// The Dear ImGui panel, docked beside the picture: errors first, then the
// viewer's buttons and readouts, then a group of controls per Program, as
// glman had (uniforms of the same name in several Programs are one control).
#include <algorithm>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <imgui.h>

#include "plan/limits.h"
#include "view/panel.h"
#include "view/panel_watch.h"
#include "view/view_model.h"

namespace glimmer {
namespace {

ImFont* gMono = nullptr;  // DejaVu Sans Mono: messages with a caret under a column
float gFontsScale = 0;    // the scale the ImGui context's fonts were last made at (0: not yet)

bool isIntType(const Renderer& r, int program, const std::string& name) {
    return r.uniformKind(program, name) == Renderer::UniformKind::Int;
}

// "1 0.5 0.2" (or with `sep` between: the `panel` command's "1,0.5,0.2").
std::string valuesText(const std::vector<double>& v, const char* sep = " ") {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : sep) + fmt::format("{:g}", x);
    return s;
}

// One control: a slider, checkbox or colour that sets the uniform in every
// Program it stands for. Constants and arrays are shown read-only.
void control(ViewerState& s, const UniformControl& c) {
    const UniformSetting& u = *c.setting;
    int p = c.programs.front();
    std::vector<double> v = s.values->get(p, u.name);
    if (v.empty()) return;
    std::string label = c.label();
    bool changed = false;
    switch (u.form) {
    case UniformSetting::Form::Range:
        if (isIntType(*s.renderer, p, u.name)) {
            int i = clampToInt(v[0]);
            changed = ImGui::SliderInt(label.c_str(), &i, clampToInt(u.min), clampToInt(u.max));
            v[0] = i;
        } else {
            float f = float(v[0]);
            changed = ImGui::SliderFloat(label.c_str(), &f, float(u.min), float(u.max));
            v[0] = f;
        }
        break;
    case UniformSetting::Form::Bool: {
        bool b = v[0] != 0;
        changed = ImGui::Checkbox(label.c_str(), &b);
        v[0] = b ? 1 : 0;
        break;
    }
    case UniformSetting::Form::Color: {
        float col[4] = {float(v[0]), float(v[1]), float(v[2]), float(v[3])};
        changed = ImGui::ColorEdit4(label.c_str(), col);
        v = {col[0], col[1], col[2], col[3]};
        break;
    }
    case UniformSetting::Form::Array:
    case UniformSetting::Form::Constant:
        ImGui::TextDisabled("%s = %s", u.name.c_str(), valuesText(v).c_str());
        break;
    }
    if (u.form == UniformSetting::Form::Range || u.form == UniformSetting::Form::Color) rememberControl(s, u.name, ImGui::CalcItemWidth());
    else rememberControl(s, u.name);
    if (changed)
        for (int q : c.programs) s.values->set(q, u.name, v);
    if (c.programs.size() > 1 && ImGui::BeginPopupContextItem(label.c_str())) {
        if (ImGui::MenuItem("Split per pass")) s.splitUniforms.push_back(u.name);
        rememberControl(s, "Split per pass");
        ImGui::EndPopup();
    }
}

// A uniform the shaders read and the script never sets (it is 0 until moved
// here): a slider from 0 to 1 (an int's to 10), a checkbox, or a drag per
// component, so a student sees what it does; the tooltip gives the line
// that keeps a value in the script. A reload that works forgets it, as
// the script does not have it.
int componentsOf(const UnsetUniform& u) { return u.type == "vec2" ? 2 : u.type == "vec3" ? 3 : u.type == "vec4" ? 4 : 1; }

void unsetControl(ViewerState& s, int program, const UnsetUniform& u) {
    std::vector<double> v = s.values->get(program, u.name);
    int n = componentsOf(u);
    if (u.size != 1 || (n == 1 && u.type != "float" && u.type != "int" && u.type != "bool")) {
        ImGui::TextDisabled("%s %s = 0 (not set by the script)", u.type.c_str(), u.name.c_str());
        return;
    }
    v.resize(size_t(n), 0.0);
    std::string label = u.name + "  (not set)";
    bool changed = false;
    if (u.type == "int") {
        int i = clampToInt(v[0]);
        changed = ImGui::SliderInt(label.c_str(), &i, 0, 10);
        v[0] = i;
    } else if (u.type == "bool") {
        bool b = v[0] != 0;
        changed = ImGui::Checkbox(label.c_str(), &b);
        v[0] = b ? 1 : 0;
    } else {
        float f[4] = {float(v[0]), n > 1 ? float(v[1]) : 0.f, n > 2 ? float(v[2]) : 0.f, n > 3 ? float(v[3]) : 0.f};
        changed = n == 1 ? ImGui::SliderFloat(label.c_str(), f, 0.f, 1.f) : ImGui::DragScalarN(label.c_str(), ImGuiDataType_Float, f, n, 0.01f);
        for (int k = 0; k < n; ++k) v[size_t(k)] = f[k];
    }
    rememberControl(s, u.name, u.type == "bool" ? 0.f : ImGui::CalcItemWidth());
    if (ImGui::IsItemHovered() && !u.example.empty())
        ImGui::SetTooltip("not in the script: add '%s' to the Program line to keep a value", u.example.c_str());
    if (changed) s.values->set(program, u.name, v);
}

bool hasSlider(const std::vector<const UniformControl*>& controls) {
    for (const auto* c : controls) {
        auto f = c->setting->form;
        if (f == UniformSetting::Form::Range || f == UniformSetting::Form::Bool || f == UniformSetting::Form::Color)
            return true;
    }
    return false;
}

// The controls, grouped under the first Program each belongs to. Every group
// with a slider starts open.
void controls(ViewerState& s) {
    const Plan& plan = s.good->plan;
    auto all = mergedUniforms(plan, s.splitUniforms);
    for (size_t p = 0; p < plan.programs.size(); ++p) {
        const ProgramDecl& decl = plan.programs[p];
        std::vector<const UniformControl*> mine;
        for (const auto& c : all)
            if (c.programs.front() == int(p)) mine.push_back(&c);
        std::vector<UnsetUniform> unset = s.renderer ? s.renderer->unsetUniforms(int(p)) : std::vector<UnsetUniform>{};
        bool mergedAway = mine.empty() && !decl.uniforms.empty() && unset.empty();
        if (mergedAway) continue;  // every uniform it has is a control of an earlier group
        ImGui::PushID(int(p));
        std::string header = fmt::format("{}  (line {})###program", decl.name, decl.loc.line);
        // Open when it has a slider of its own (a merged one lives in the
        // first Program's group).
        bool sliders = hasSlider(mine) || !unset.empty();
        const bool open = ImGui::CollapsingHeader(header.c_str(), sliders ? ImGuiTreeNodeFlags_DefaultOpen : 0);
        rememberControl(s, "Program " + decl.name);  // the group's header: a click folds it
        if (open) {
            if (!decl.notes.empty()) {  // what the script says this pass does (MessageBox, ## comments)
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.85f, 1.f, 1.f));
                ImGui::TextWrapped("%s", decl.notes.c_str());
                ImGui::PopStyleColor();
            }
            for (const auto* c : mine) control(s, *c);
            if (!unset.empty()) {
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.8f, 0.35f, 1.f));
                ImGui::TextWrapped("read by the shaders, never set by the script (0 until moved here):");
                ImGui::PopStyleColor();
                for (const auto& u : unset) unsetControl(s, int(p), u);
            }
            const bool reset = sliders && ImGui::Button("Reset");
            if (sliders) rememberControl(s, "Reset " + decl.name);
            if (reset) {
                for (const auto* c : mine)
                    for (int q : c->programs) s.values->set(q, c->name, c->setting->values);
                // Back to the 0 OpenGL gave them (an empty value would upload
                // nothing and leave the program's last one).
                for (const auto& u : unset)
                    if (!s.values->get(int(p), u.name).empty()) s.values->set(int(p), u.name, std::vector<double>(size_t(componentsOf(u)), 0.0));
            }
        }
        ImGui::PopID();
    }
    if (!s.splitUniforms.empty()) {
        if (ImGui::SmallButton("Merge same-name uniforms again")) s.splitUniforms.clear();
        rememberControl(s, "Merge");
    }
}

// Errors first, each a line to click (copies file:line); the full message
// in a monospace font so the caret sits under its column. Warnings fold
// into a count.
void messages(ViewerState& s) {
    if (s.failed) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.45f, 0.4f, 1.f));
        ImGui::TextUnformatted(fmt::format("{} error{}: showing the last picture that worked", s.errors.size(),
                                           s.errors.size() == 1 ? "" : "s")
                                   .c_str());
        ImGui::PopStyleColor();
        for (size_t i = 0; i < s.errors.size(); ++i) {
            ImGui::PushID(int(i));
            if (gMono) ImGui::PushFont(gMono);
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.55f, 0.5f, 1.f));
            // Wrapped, not cut at the panel's edge; a click on it copies as a Selectable did.
            ImGui::TextWrapped("%s", s.errors[i].text.c_str());
            const bool copy = ImGui::IsItemClicked();
            if (ImGui::IsItemHovered())
                ImGui::GetWindowDrawList()->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), IM_COL32(255, 140, 128, 160));
            rememberControl(s, fmt::format("Error {}", i + 1));
            if (copy) {
                ImGui::SetClipboardText(s.errors[i].where.c_str());
                s.status = "copied " + s.errors[i].where;
                std::cerr << "glimmer view: " << s.status << "\n";
            }
            ImGui::PopStyleColor();
            if (gMono) ImGui::PopFont();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("click to copy %s", s.errors[i].where.c_str());
            ImGui::PopID();
        }
    }
    if (!s.warnings.empty()) {
        const size_t n = warningCount(s);
        std::string label = n ? fmt::format("{} warning{}###warnings", n, n == 1 ? "" : "s") : "notes###warnings";
        const bool open = ImGui::TreeNode(label.c_str());
        rememberControl(s, "Warnings");
        if (open) {
            if (gMono) ImGui::PushFont(gMono);
            for (const auto& w : s.warnings) ImGui::TextColored(ImVec4(1.f, 0.8f, 0.35f, 1.f), "%s", w.text.c_str());
            rememberControl(s, "Warnings open");  // the last one, shown
            if (gMono) ImGui::PopFont();
            ImGui::TreePop();
        }
    }
}

std::string targetName(const Plan& plan, int tex) {
    if (tex < 0) return "screen";
    for (const auto& [unit, t] : plan.finalUnits)
        if (t == tex) return fmt::format("unit {}", unit);
    return fmt::format("texture {}", tex);
}

// A list of the targets; its items are remembered as "LABEL: NAME" while it is open.
bool targetCombo(ViewerState& s, const char* label, const Plan& plan, const std::vector<std::pair<int, unsigned>>& targets,
                 int& shown) {
    bool changed = false;
    const bool open = ImGui::BeginCombo(label, targetName(plan, shown).c_str());
    rememberControl(s, label, ImGui::CalcItemWidth());
    if (open) {
        if (ImGui::Selectable("screen", shown < 0)) shown = -1, changed = true;
        rememberControl(s, fmt::format("{}: screen", label));
        for (const auto& [tex, name] : targets) {
            if (ImGui::Selectable(targetName(plan, tex).c_str(), shown == tex)) shown = tex, changed = true;
            rememberControl(s, fmt::format("{}: {}", label, targetName(plan, tex)));
        }
        ImGui::EndCombo();
    }
    return changed;
}

}  // namespace

void rememberControl(ViewerState& s, const std::string& name, float frameWidth) {
    const ImVec2 at = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
    s.controlRects[name] = {at.x, at.y, frameWidth > 0 ? std::min(size.x, frameWidth) : size.x, size.y};
    if (ImGui::IsItemActive()) s.activeControl = name;
}

void setUpFonts(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    const char* dirs[] = {"/usr/share/fonts/truetype/dejavu/", "/usr/share/fonts/dejavu/", "/usr/share/fonts/TTF/",
                          "/usr/local/share/fonts/", "/usr/share/fonts/truetype/"};
    auto find = [&](const char* file) -> std::string {
        for (const char* d : dirs) {
            std::error_code ec;
            if (std::filesystem::exists(std::string(d) + file, ec)) return std::string(d) + file;
        }
        return {};
    };
    std::string sans = find("DejaVuSans.ttf"), mono = find("DejaVuSansMono.ttf");
    // Called again when the scale changes (a `scale` command, a move to a
    // monitor of another content scale): fonts made afresh, sizes scaled from
    // ImGui's own, never from an already scaled style.
    io.Fonts->Clear();
    static const ImGuiStyle unscaled = ImGui::GetStyle();
    ImGui::GetStyle() = unscaled;
    float px = std::round(kPanelFontPx * scale);
    ImFontConfig cfg;
    cfg.OversampleH = 2;  // rasterised at the size it is shown: crisp, not a blown-up bitmap
    if (!sans.empty() && io.Fonts->AddFontFromFileTTF(sans.c_str(), px, &cfg)) {
        std::cerr << fmt::format("glimmer view: font {} at {:g} px\n", sans, px);
    } else {
        std::cerr << "glimmer view: warning: DejaVu Sans not found (install fonts-dejavu-core); using ImGui's "
                     "built-in font\n";
        ImFontConfig def;
        def.SizePixels = std::round(13.f * scale);
        io.Fonts->AddFontDefault(&def);
    }
    gMono = !mono.empty() ? io.Fonts->AddFontFromFileTTF(mono.c_str(), std::round(14.f * scale), &cfg) : nullptr;
    ImGui::GetStyle().ScaleAllSizes(scale);
    gFontsScale = scale;
}

float fontsScale() { return gFontsScale; }

std::string panelState(const ViewerState& s, const std::optional<WatchRange>& range, int loads) {
    auto word = [](std::string v) {
        std::string out;
        for (char c : v) out += c == ' ' ? "%20" : c == '%' ? "%25" : c == '\n' ? "%0A" : std::string(1, c);
        return out.empty() ? std::string("-") : out;
    };
    auto onOff = [](bool b) { return b ? "on" : "off"; };
    std::string line = fmt::format("panel loads={} values={} size={}x{} aspect={} playing={} time={:.3f} view={:g},{:g},{:g}",
                                   loads, onOff(s.showValues), s.hardcopy[0], s.hardcopy[1], onOff(s.hardcopyAspect),
                                   onOff(s.playing), s.time, s.yaw, s.pitch, s.zoom);
    if (s.good) {
        const Plan& plan = s.good->plan;
        line += fmt::format(" shown={} split={} left={} right={} divider={:.2f}", word(targetName(plan, s.shownTexture)),
                            onOff(s.compare), word(targetName(plan, s.compareLeft)), word(targetName(plan, s.compareRight)),
                            s.divider);
    }
    line += fmt::format(" active={} probe={} watch={} range={} errors={} status={}", word(s.activeControl), onOff(s.probe), word(s.watch ? s.watchSpec : ""),
                        range ? fmt::format("{:g},{:g}", range->lo, range->hi) : "auto", s.errors.size(), word(s.status));
    if (s.good && s.values) {
        for (const auto& c : mergedUniforms(s.good->plan, s.splitUniforms)) {
            line += fmt::format(" {}={}", word(c.name), word(valuesText(s.values->get(c.programs.front(), c.name), ",")));
        }
        if (s.renderer)  // the ones the shaders read and the script never sets, once moved
            for (size_t p = 0; p < s.good->plan.programs.size(); ++p)
                for (const auto& u : s.renderer->unsetUniforms(int(p)))
                    line += fmt::format(" {}={}", word(u.name), word(valuesText(s.values->get(int(p), u.name), ",")));
    }
    return line;
}

std::string overlayText(const ViewerState& s) {
    if (!s.good || !s.values) return {};
    std::string text;
    for (const auto& c : mergedUniforms(s.good->plan, s.splitUniforms)) {
        auto f = c.setting->form;
        if (f != UniformSetting::Form::Range && f != UniformSetting::Form::Bool && f != UniformSetting::Form::Color) continue;
        text += fmt::format("{}{} = {}", text.empty() ? "" : "\n", c.label(), valuesText(s.values->get(c.programs.front(), c.name)));
    }
    return text;
}

std::vector<ViewCommand> drawPanel(ViewerState& s, const std::vector<std::pair<int, unsigned>>& thumbnails) {
    std::vector<ViewCommand> asked;
    s.controlRects.clear();
    s.activeControl.clear();
    float em = ImGui::GetFontSize();
    ImGui::PushItemWidth(em * 11);  // a fixed width: the panel's width follows its content
    // Text wraps at 30 em, or inside the width the shell pins the panel to
    // (the page's): a message is never cut at the panel's edge.
    const float pad = ImGui::GetStyle().WindowPadding.x;
    ImGui::PushTextWrapPos(s.panelMaxW > 0 ? std::min(em * 30, s.panelMaxW - pad) : em * 30);
    if (s.good) ImGui::TextUnformatted(s.good->plan.scriptFile.c_str());
    messages(s);
    auto command = [](ViewCommand::Kind kind, std::string file = {}) {
        ViewCommand c;
        c.kind = kind;
        c.name = std::move(file);
        return c;
    };
    // Each control remembered under the name its label starts with.
    if (ImGui::Button("Reload (R)")) asked.push_back(command(ViewCommand::Kind::Reload));
    rememberControl(s, "Reload");
    ImGui::SameLine();
    if (ImGui::Button("Save PNG (S)")) asked.push_back(command(ViewCommand::Kind::Save));  // a new name each time
    rememberControl(s, "Save PNG");
    ImGui::SameLine();
    ImGui::Checkbox("Show values", &s.showValues);
    rememberControl(s, "Show values");
    ImGui::SetNextItemWidth(em * 8);
    int before[2] = {s.hardcopy[0], s.hardcopy[1]};
    if (ImGui::InputInt2("##size", s.hardcopy) && s.hardcopyAspect && s.pictureW > 0) {
        // Keep the picture's aspect: the other side follows the one typed.
        if (s.hardcopy[0] != before[0]) s.hardcopy[1] = std::max(1, int(std::lround(double(s.hardcopy[0]) * s.pictureH / s.pictureW)));
        else if (s.hardcopy[1] != before[1]) s.hardcopy[0] = std::max(1, int(std::lround(double(s.hardcopy[1]) * s.pictureW / s.pictureH)));
    }
    rememberControl(s, "Size", em * 8);  // two fields: the width's is the left half
    ImGui::SameLine();
    ImGui::Checkbox("aspect", &s.hardcopyAspect);
    rememberControl(s, "aspect");
    ImGui::SameLine();
    if (ImGui::Button("Save at size")) {
        ViewCommand c = command(ViewCommand::Kind::Save, nextFreeName("glimmer-hardcopy", ".png"));
        c.unit = -2;  // marks a hardcopy at s.hardcopy
        asked.push_back(c);
    }
    rememberControl(s, "Save at size");
    if (ImGui::Button(s.playing ? "Pause (space)" : "Play (space)")) s.playing = !s.playing;
    rememberControl(s, "Play");
    ImGui::SameLine();
    if (ImGui::Button("Step")) {
        s.playing = false;
        s.time += 1.0 / 30.0;
    }
    rememberControl(s, "Step");
    ImGui::SameLine();
    ImGui::Text("t = %.2f s", s.time);
    if (s.turns) {
        if (ImGui::Button("Reset view (0)")) {
            s.yaw = s.pitch = 0;
            s.zoom = 1;
            s.sceneMoved = true;
        }
        rememberControl(s, "Reset view");
        ImGui::SameLine();
        ImGui::TextDisabled("drag: turn, wheel: zoom");
    } else {
        ImGui::TextDisabled("a flat picture: the mouse does not turn it");
    }
    if (!s.keyHint.empty()) ImGui::TextDisabled("%s", s.keyHint.c_str());
    // The sliders next, near the top where a projector shows them: the
    // teaching aids below may grow (a watch's summary) without pushing
    // them out of the window.
    if (s.good) controls(s);

    if (s.good) {
        const Plan& plan = s.good->plan;
        // Teaching aids: the pass inspector with a thumbnail of every target,
        // a before/after split, a probe of the value under the pointer.
        targetCombo(s, "show", plan, thumbnails, s.shownTexture);
        float th = std::round(em * 4);
        for (size_t i = 0; i < thumbnails.size(); ++i) {
            const auto& [tex, name] = thumbnails[i];
            if (!name) continue;
            if (i % 5 != 0) ImGui::SameLine();  // five to a row
            ImGui::BeginGroup();
            ImGui::PushID(tex);
            // Flipped: OpenGL's row 0 is the bottom.
            if (ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(name)), ImVec2(th, th), ImVec2(0, 1),
                                   ImVec2(1, 0), s.shownTexture == tex ? 3 : 1))
                s.shownTexture = s.shownTexture == tex ? -1 : tex;
            rememberControl(s, "Thumbnail " + targetName(plan, tex));
            ImGui::PopID();
            ImGui::TextDisabled("%s", targetName(plan, tex).c_str());
            ImGui::EndGroup();
        }
        ImGui::Checkbox("Before/after split", &s.compare);
        rememberControl(s, "Before/after split");
        if (s.compare) {
            if (s.compareLeft == s.compareRight && !thumbnails.empty()) s.compareLeft = thumbnails.back().first;
            targetCombo(s, "left", plan, thumbnails, s.compareLeft);
            targetCombo(s, "right", plan, thumbnails, s.compareRight);
            ImGui::SliderFloat("divider", &s.divider, 0.f, 1.f);
            rememberControl(s, "divider", ImGui::CalcItemWidth());
            ImGui::TextDisabled("drag across the picture to move it");
        }
        ImGui::Checkbox("Probe (hover the picture)", &s.probe);
        rememberControl(s, "Probe");
        if (!s.probeText.empty()) ImGui::TextUnformatted(s.probeText.c_str());
        watchControls(s, asked);

        // Timings fold away, so the sliders stay near the top. A picture
        // drawn in slices shows its progress on the same line, so nothing
        // below moves (a slider being dragged stays under the pointer).
        std::string timings =
            s.drawing >= 0 ? fmt::format("drawing... {:.0f}% (last frame {:.1f} ms)###timings", 100.0 * s.drawing, s.lastFrameMs)
                           : fmt::format("frame {:.1f} ms, {} pass{}###timings", s.lastFrameMs, s.lastTimings.size(),
                                         s.lastTimings.size() == 1 ? "" : "es");
        const bool timingsOpen = ImGui::TreeNode(timings.c_str());
        rememberControl(s, "Timings");
        if (timingsOpen) {
            for (const auto& t : s.lastTimings) ImGui::Text("%s: %.2f ms", passName(plan, t.pass).c_str(), t.ms);
            rememberControl(s, "Timings open");  // the last pass's line, shown
            ImGui::TreePop();
        }
        // A warning badge for any target holding NaN, Inf, negatives or
        // values past the half-float range (see render --health).
        for (const auto& h : s.health) {
            if (!h.bad()) continue;
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.75f, 0.2f, 1.f));
            ImGui::TextWrapped("(!) %s: %zu NaN, %zu Inf, %zu negative, %zu above 65504", h.name.c_str(), h.health.nan,
                               h.health.inf, h.health.negative, h.health.above65504);
            ImGui::PopStyleColor();
            if (!s.controlRects.count("Health")) rememberControl(s, "Health");  // the first badge, for `where Health`
        }
    }
    if (!s.status.empty()) ImGui::TextDisabled("%s", s.status.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
    return asked;
}

std::vector<ViewCommand> drawPanelWindow(ViewerState& s, float x, float height, int& width, int& contentHeight) {
    ImGui::SetNextWindowPos(ImVec2(x, 0.f), ImGuiCond_Always);
    // Width 0: ImGui fits the panel's width to its content every frame.
    ImGui::SetNextWindowSize(ImVec2(0.f, height), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.f);
    ImGui::Begin("Glimmer", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
    std::vector<std::pair<int, unsigned>> thumbs;
    if (s.renderer)
        for (int t : s.renderer->renderTargets()) thumbs.push_back({t, s.renderer->textureName(t)});
    auto asked = drawPanel(s, thumbs);
    contentHeight = int(ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y + 1);
    width = int(ImGui::GetWindowWidth());
    ImGui::End();
    return asked;
}

}  // namespace glimmer
