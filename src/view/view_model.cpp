#include "view/view_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

namespace glimmer {

bool sceneTurns(const Plan& plan) {
    for (const auto& pass : plan.passes) {
        if (!pass.targets.empty() || !pass.needed) continue;
        for (const auto& st : pass.steps) {
            if (st.kind != Step::Kind::Draw || st.draw.mesh < 0) continue;
            // An orthographic projection has a bottom row of (0 0 0 1).
            bool perspective = st.draw.projection[0][3] != 0.f || st.draw.projection[1][3] != 0.f ||
                               st.draw.projection[2][3] != 0.f;
            if (perspective || !plan.meshes[size_t(st.draw.mesh)].flat()) return true;
        }
    }
    return false;
}

std::string passName(const Plan& plan, int p) {
    const Pass& pass = plan.passes[size_t(p)];
    std::string program;
    for (const auto& st : pass.steps)
        if (st.kind == Step::Kind::Draw && st.draw.program >= 0) {
            const ProgramDecl& decl = plan.programs[size_t(st.draw.program)];
            program = fmt::format("{} (line {})", decl.name, decl.loc.line);
            break;
        }
    if (program.empty()) program = fmt::format("line {}", pass.loc.line);
    std::string into = "screen";
    if (!pass.targets.empty()) {
        into.clear();
        for (int t : pass.targets) {
            int unit = -1;
            for (const auto& [u, tex] : plan.finalUnits)
                if (tex == t) unit = u;
            into += (into.empty() ? "" : ", ") + (unit >= 0 ? fmt::format("unit {}", unit) : fmt::format("texture {}", t));
        }
    }
    return program + " -> " + into;
}

std::string UniformControl::label() const {
    return programs.size() > 1 ? fmt::format("{} - {} passes", name, programs.size()) : name;
}

std::vector<UniformControl> mergedUniforms(const Plan& plan, const std::vector<std::string>& split) {
    std::vector<UniformControl> out;
    for (size_t p = 0; p < plan.programs.size(); ++p)
        for (const auto& u : plan.programs[p].uniforms) {
            bool merges = u.form == UniformSetting::Form::Range || u.form == UniformSetting::Form::Bool ||
                          u.form == UniformSetting::Form::Color;
            bool isSplit = std::find(split.begin(), split.end(), u.name) != split.end();
            UniformControl* into = nullptr;
            if (merges && !isSplit)
                for (auto& c : out) {
                    const UniformSetting& s = *c.setting;
                    if (c.name == u.name && s.form == u.form && s.min == u.min && s.max == u.max) into = &c;
                }
            if (into) {
                into->programs.push_back(int(p));
                continue;
            }
            out.push_back({u.name, {int(p)}, &u});
        }
    return out;
}

std::string nextFreeName(const std::string& stem, const std::string& ext) {
    for (int i = 1;; ++i) {
        std::string name = fmt::format("{}-{:03}{}", stem, i, ext);
        std::error_code ec;
        if (!std::filesystem::exists(name, ec)) return name;
    }
}

void sizeWithAspect(int pictureW, int pictureH, int longSide, int& w, int& h) {
    pictureW = std::max(pictureW, 1);
    pictureH = std::max(pictureH, 1);
    if (pictureW >= pictureH) {
        w = longSide;
        h = std::max(1, int(std::lround(double(longSide) * pictureH / pictureW)));
    } else {
        h = longSide;
        w = std::max(1, int(std::lround(double(longSide) * pictureW / pictureH)));
    }
}

WindowLayout layoutWindow(int pictureW, int pictureH, bool panelShown, int panelW, int panelH, int maxHeight) {
    WindowLayout l;
    l.panelX = pictureW;
    l.panelW = panelShown ? panelW : 0;
    l.windowW = pictureW + l.panelW;
    l.windowH = std::max(pictureH, panelShown ? std::min(panelH, maxHeight) : 0);
    return l;
}

float chooseUiScale(double option, float monitorScaleX, float monitorScaleY) {
    if (option > 0) return float(option);
    float monitor = std::max(monitorScaleX, monitorScaleY);
    return std::isfinite(monitor) ? std::max(1.f, monitor) : 1.f;
}

std::string helpText() {
    return "commands (one a line on standard input, or ';'-separated in --exec):\n"
           "  set NAME VALUE     set a uniform (every Program that has it)\n"
           "  reload             load the script again\n"
           "  save FILE.png      save what is shown (the picture, or the inspected target)\n"
           "  show UNIT|screen   inspect the render target on a texture unit, or the picture\n"
           "  values on|off      the \"Show values\" overlay (also burned into saves)\n"
           "  probe on|off       the pixel probe; \"probe\" alone prints what it reads under the pointer\n"
           "  probe X Y          prints pixel (X, Y) of the finished picture (top left 0 0)\n"
           "  split L R | off    before/after split: unit L (or screen) left, R right of the divider\n"
           "  watch FILE:LINE EXPR   show EXPR's value over its pass, right after line LINE of FILE runs\n"
           "  watch range LO,HI|auto   the watch's values shown black to white; auto: their own range\n"
           "  watch off          back to the picture\n"
           "  where CONTROL      prints where the panel's control is: X Y W H in window pixels\n"
           "  panel              prints what the panel shows: its switches, the watch and every value\n"
           "  scale S            the panel's text and controls at S (0.5 to 4), as --ui-scale\n"
           "  help               print this list\n"
           "  frames             print frame times since the last 'frames' and the last picture's time\n"
           "  quit               close the window\n"
           "keys (over the window):\n"
           "  space  pause / play Timer        H  hide / show the panel\n"
           "  F      fullscreen                R  reload\n"
           "  0      reset the view            S  save PNG (a new name each time)\n"
           "  Q, Esc quit\n"
           "mouse: drag to turn, wheel to zoom (perspective or solid scenes only)\n";
}

}  // namespace glimmer
