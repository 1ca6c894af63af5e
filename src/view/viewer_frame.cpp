// The frame of the window and the page, once (view/viewer_core.h): the
// order of its steps, what the panel and the keys leave for the shell, the
// panel's fonts at the ui scale, the numeric health and the files a load
// read. The shells only make the context, read their platform's input and
// present.
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "gl/window_frame.h"
#include "view/panel.h"
#include "view/view_model.h"
#include "view/viewer_core.h"

namespace glimmer {

bool ViewerCore::startFrames(std::string& why) {
    if (!windowFrame_) windowFrame_ = WindowFrame::create(getProc_, why);
    return windowFrame_ != nullptr;
}

void ViewerCore::followUiScale(ViewerHost& host) {
    if (fontsScale() == uiScale_) return;  // made at this scale already, by this core or the last
    setUpFonts(uiScale_);
    // The backend made its font texture at the first frame: made again at the
    // new size (before it, the first NewFrame makes it from these fonts).
    if (ImGui::GetIO().Fonts->TexID) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
    host.say(fmt::format("ui scale {:g}", uiScale_));
}

void ViewerCore::frame(const FrameGeometry& g, ViewerHost& host) {
    followUiScale(host);
    ImGui_ImplOpenGL3_NewFrame();
    host.platformFrame();
    ImGui::NewFrame();
    host.input();
    draw(g.budgetMs);
    noteHealth(host);

    // The probe under a pointer that rests on the picture (not on the panel,
    // not while it drags the scene or a slider).
    const ImGuiIO& io = ImGui::GetIO();
    const double x = io.MousePos.x - g.pictureX, y = io.MousePos.y - g.pictureY;
    if (!io.WantCaptureMouse && !io.MouseDown[0] && x >= 0 && y >= 0 && x < g.pictureW && y < g.pictureH)
        probe(x, y, g.pictureW, g.pictureH);
    else
        s_.probeText.clear();

    std::vector<ViewCommand> asked;
    if (s_.panelShown) {
        s_.panelMaxW = g.panelMaxW;
        if (g.panelMaxW > 0)
            ImGui::SetNextWindowSizeConstraints(ImVec2(0.f, 0.f), ImVec2(g.panelMaxW, std::numeric_limits<float>::max()));
        asked = drawPanelWindow(s_, g.panelX, float(g.windowH), panelW_, panelH_);
    }
    // The picture too has a place a tour can find (`where Picture`): a drag there turns the scene.
    s_.controlRects["Picture"] = {float(g.pictureX), float(g.pictureY), float(g.pictureW), float(g.pictureH)};
    drawValues();
    ImGui::Render();
    if (windowFrame_) windowFrame_->begin(g.windowW, g.windowH, 0.12f, 0.12f, 0.14f);
    presentPicture(s_, g.windowH, g.pictureX, g.pictureY, g.pictureW, g.pictureH);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (pictureHashWanted_ && windowFrame_) {  // asked by `panel`: the picture as shown, the values box on it
        pictureHash_ = windowFrame_->hashRegion(g.pictureX, g.pictureY, g.pictureW, g.pictureH, g.windowH);
        pictureHashWanted_ = false;
    }
    noteFrame();

    // What the panel's buttons and the keys asked, after the frame is shown.
    asked.insert(asked.end(), keyAsks_.begin(), keyAsks_.end());
    keyAsks_.clear();
    for (const auto& c : asked) command(c, host);
}

void ViewerCore::command(const ViewCommand& c, ViewerHost& host) {
    std::string said;
    if (apply(c, said)) {  // what only changes what is shown
        std::istringstream lines(said);
        for (std::string line; std::getline(lines, line);) host.say(line);
        return;
    }
    switch (c.kind) {
    case ViewCommand::Kind::Quit: host.quit(); break;
    case ViewCommand::Kind::Help: host.print(helpText(), true); break;
    case ViewCommand::Kind::Frames: host.print(frameStats(), true); break;
    case ViewCommand::Kind::Scale: host.scale(float(c.value)); break;
    case ViewCommand::Kind::Reload: host.reload(); break;
    case ViewCommand::Kind::Save: host.save(c.name, c.unit == -2); break;
    default: break;
    }
}

KeyAction ViewerCore::key(std::string_view name) {
    const KeyAction action = keyAction(name);
    if (applyStateKey(action, s_)) return action;
    ViewCommand c;
    if (action == KeyAction::Reload) c.kind = ViewCommand::Kind::Reload;
    else if (action == KeyAction::Save) c.kind = ViewCommand::Kind::Save;
    else if (action == KeyAction::Quit) c.kind = ViewCommand::Kind::Quit;
    else return action;
    keyAsks_.push_back(c);
    return action;
}

bool ViewerCore::set(const std::string& assignment, Diagnostics& diags) {
    if (!s_.good || !s_.values) return false;
    return s_.values->applySet(s_.good->plan, assignment, diags) && !diags.hasErrors();
}

Image ViewerCore::sheet(const SheetRequest& r) {
    if (!s_.good || !s_.renderer) return {};
    Image out = drawSheet(*s_.renderer, s_.good->plan, *s_.values, r.cols, r.rows, r.title);
    s_.drawAll = true;
    return out;
}

bool ViewerCore::pointer(double x, double y, bool down, float wheel, bool captured, int px, int py, int pw, int ph) {
    return pointerOnPicture(s_, drag_, x, y, down, wheel, captured, px, py, pw, ph);
}

void ViewerCore::advance(double seconds) {
    if (s_.playing && seconds > 0) s_.time += seconds;
}

void ViewerCore::noteHealth(ViewerHost& host, bool right) {
    const auto now = Clock::now();
    if (!s_.good || !s_.renderer || pictureVersion_ == healthVersion_ ||
        (!right && now - lastHealth_ < std::chrono::milliseconds(500)))
        return;
    healthVersion_ = pictureVersion_;
    lastHealth_ = now;
    s_.health = measureHealth(*s_.renderer, s_.good->plan);
    std::string report;
    for (const auto& h : s_.health)
        if (h.bad()) report += formatHealth(h) + "\n";
    if (report != healthReport_ && !report.empty()) host.print(report, false);  // once per change
    healthReport_ = report;
}

void ViewerCore::noteFiles(const Plan& plan) {
    std::vector<std::string> edited = {source_.script};
    std::set<std::string> read(readFiles_.begin(), readFiles_.end());
    read.insert(source_.script);
    for (const auto& program : plan.programs)
        for (const auto& stage : program.stages) {
            read.insert(stage.path);
            if (!stage.path.empty() && std::find(edited.begin(), edited.end(), stage.path) == edited.end())
                edited.push_back(stage.path);
        }
    for (const auto& t : plan.textures) {
        if (t.source == TextureDecl::Source::File) read.insert(t.path);
        read.insert(t.facePaths.begin(), t.facePaths.end());  // all six faces of a cube map
    }
    for (const auto& m : plan.meshes) read.insert(m.path);  // OBJ models
    read.erase("");  // a missing file with a stand-in (--stand-ins), a shape with no model
    readFiles_.assign(read.begin(), read.end());
    // A load that named no Program (an error before them) keeps the last list.
    if (!plan.programs.empty() || scriptFiles_.empty()) scriptFiles_ = edited;
}

}  // namespace glimmer
