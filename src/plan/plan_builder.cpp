// Walks the commands in script order, keeping glman's state (matrices,
// colour, current shaders, texture units) and writing passes of draws.
#include "plan/builder.h"
#include "plan/limits.h"
#include "plan/hidden_clears.h"
#include "plan/memory_budget.h"
#include "geometry/planarity.h"
#include "geometry/shape_registry.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

namespace glimmer {
namespace plan_detail {

Plan Builder::build() {
    plan_.scriptFile = script_.file;
    // The size must be known before any matrix is computed: --size wins,
    // then the first WindowSize, then glman's 600x600.
    for (const auto& c : script_.commands) {
        if (c.kind == CommandKind::WindowSize) {
            // Checked before converting (1e47 does not fit an int);
            // reported by the walk below.
            if (c.args.size() == 2 && c.args[0].kind == Arg::Kind::Number && c.args[1].kind == Arg::Kind::Number &&
                wholeIn(c.args[0].number, 1, 16384) && wholeIn(c.args[1].number, 1, 16384)) {
                plan_.width = int(c.args[0].number);
                plan_.height = int(c.args[1].number);
            }
            break;
        }
    }
    if (options_.width > 0 && options_.height > 0) {
        plan_.width = options_.width;
        plan_.height = options_.height;
    }
    plan_.passes.push_back(Pass{});
    for (const auto& c : script_.commands) command(c);
    if (imm_) {
        diags_.warning(file(), imm_->step.draw.loc, "glBegin without glEnd; drawn as if the script ended it");
        glEnd(nullptr);
    }
    plan_.finalUnits = units_;
    finish();
    return std::move(plan_);
}

// Checks that a command has between lo and hi arguments, all numbers.
bool Builder::numbers(const Command& c, size_t lo, size_t hi) {
    if (c.args.size() < lo || c.args.size() > hi) {
        std::string want = lo == hi ? fmt::format("{}", lo) : fmt::format("{} to {}", lo, hi);
        diags_.error(file(), c.loc, fmt::format("{} takes {} number{}, got {}", c.spelled, want,
                                                hi == 1 ? "" : "s", c.args.size()));
        return false;
    }
    for (const auto& a : c.args) {
        if (a.kind != Arg::Kind::Number) {
            diags_.error(file(), a.loc, fmt::format("{} takes numbers; '{}' is not a number", c.spelled,
                                                    a.text.empty() ? std::string("[...]") : a.text));
            return false;
        }
        if (!inFloatRange(a.number)) {
            diags_.error(file(), a.loc, fmt::format("{}: '{}' is out of range (at most 1e30 either way)", c.spelled, a.text));
            return false;
        }
    }
    return true;
}

double Builder::num(const Command& c, size_t i, double fallback) const {
    return i < c.args.size() ? c.args[i].number : fallback;
}

bool Builder::numbers(const Command& c) {
    const CommandRule* rule = commandRule(c.kind);
    return numbers(c, size_t(rule->minNumbers), size_t(rule->maxNumbers));
}

double Builder::num(const Command& c, size_t i) const {
    return num(c, i, commandRule(c.kind)->defaults.at(i));
}

// The aspect ratio the projection keeps. Only the screen is widened, as
// glman's window reshape does; a quad drawn to cover a texture target
// must cover it exactly, whatever the texture's shape.
std::pair<int, int> Builder::aspectSize() const {
    if (plan_.passes.back().targets.empty()) return {plan_.width, plan_.height};
    return {1, 1};
}

void Builder::command(const Command& c) {
    if (imm_ && c.kind != CommandKind::GlVertex && c.kind != CommandKind::GlEnd && c.kind != CommandKind::GlBegin)
        diags_.warning(file(), c.loc, fmt::format("only glVertex belongs between glBegin (line {}) and glEnd; {} "
                                                  "acts here, on what is drawn after it, not on this glBegin",
                                                  imm_->step.draw.loc.line, c.spelled));
    // Shapes made from numbers are one row each in geometry/shape_registry.h.
    if (const ShapeRule* rule = findShapeRule(commandName(c.kind)); rule && rule->source == ShapeRule::Source::Numbers) {
        numberShape(c, *rule);
        return;
    }
    switch (c.kind) {
    case CommandKind::WindowSize:  // read before the walk; checked here
        if (numbers(c) && (!wholeIn(c.args[0].number, 1, 16384) || !wholeIn(c.args[1].number, 1, 16384)))
            diags_.error(file(), c.loc, "WindowSize must be between 1 and 16384 pixels each way");
        break;
    case CommandKind::Ortho: ortho(c); break;
    case CommandKind::Perspective:
        if (numbers(c)) {
            projection_.kind = Projection::Kind::Perspective;
            projection_.fov = num(c, 0);
            if (!(projection_.fov > 0 && projection_.fov < 180)) {
                diags_.error(file(), c.loc, "Perspective's field of view must be between 0 and 180 degrees");
                projection_.fov = kDefaultFov;
            }
        }
        break;
    case CommandKind::LookAt: lookAt(c); break;
    case CommandKind::Translate:
        if (numbers(c)) model_ = glm::translate(model_, glm::vec3(num(c, 0), num(c, 1), num(c, 2)));
        break;
    case CommandKind::Rotate:
        if (numbers(c)) {
            glm::vec3 axis(num(c, 1), num(c, 2), num(c, 3));
            if (glm::length(axis) == 0.f)
                diags_.warning(file(), c.loc, "Rotate about a zero axis does nothing");
            else
                model_ = glm::rotate(model_, glm::radians(float(num(c, 0))), axis);
        }
        break;
    case CommandKind::Scale:
        if (c.args.size() == 1 && numbers(c, 1, 1))
            model_ = glm::scale(model_, glm::vec3(float(c.args[0].number)));
        else if (numbers(c, 3, 3))
            model_ = glm::scale(model_, glm::vec3(num(c, 0, 1), num(c, 1, 1), num(c, 2, 1)));
        break;
    case CommandKind::PushMatrix: stack_.push_back(model_); break;
    case CommandKind::PopMatrix:
        if (stack_.empty())
            diags_.warning(file(), c.loc, fmt::format("{} without a matching PushMatrix is ignored", c.spelled));
        else {
            model_ = stack_.back();
            stack_.pop_back();
        }
        break;
    case CommandKind::Background:
        if (auto v = colorArgs(c)) background_ = *v;
        break;
    case CommandKind::Color:
        if (auto v = colorArgs(c)) color_ = *v;
        break;
    case CommandKind::Clear: {
        Step s;
        s.kind = Step::Kind::Clear;
        s.clearColor = background_;
        pass().steps.push_back(s);
        break;
    }
    case CommandKind::LineWidth:
        if (numbers(c)) lineWidth_ = float(num(c, 0));
        break;
    case CommandKind::PointSize:
        if (numbers(c)) pointSize_ = float(num(c, 0));
        break;
    case CommandKind::Flat: flat_ = true; break;
    case CommandKind::Smooth: flat_ = false; break;
    case CommandKind::Timer:
        if (numbers(c)) {
            double t = num(c, 0);
            if (t > 0) plan_.timerPeriod = t;
            else diags_.error(file(), c.loc, "Timer's period must be more than 0 seconds");
        }
        break;
    case CommandKind::MessageBox:  // glman shows the text in a dialog; here it is a note on the next Program
        if (!c.args.empty()) pendingNotes_ += (pendingNotes_.empty() ? "" : "\n") + c.args[0].text;
        break;
    case CommandKind::Gstap: gstap_ = true; break;
    case CommandKind::Noise2D:
    case CommandKind::Noise3D: noiseRes(c); break;
    case CommandKind::Texture2D: texture2D(c); break;
    case CommandKind::Texture3D: texture3D(c); break;
    case CommandKind::CubeMap: cubeMap(c); break;
    case CommandKind::RenderToTexture: renderToTexture(c); break;
    case CommandKind::Wrap: wrap(c); break;
    case CommandKind::Vertex: stage(c, ShaderStage::Kind::Vertex); break;
    case CommandKind::Fragment: stage(c, ShaderStage::Kind::Fragment); break;
    case CommandKind::Geometry: stage(c, ShaderStage::Kind::Geometry); break;
    case CommandKind::TessControl: stage(c, ShaderStage::Kind::TessControl); break;
    case CommandKind::TessEvaluation: stage(c, ShaderStage::Kind::TessEvaluation); break;
    case CommandKind::Program: program(c); break;
    case CommandKind::Obj:
    case CommandKind::ObjAdj:
    case CommandKind::WireObj: obj(c); break;
    case CommandKind::Triangles: pointsMesh(c, 3); break;
    case CommandKind::LinesAdjacency: pointsMesh(c, 4); break;
    case CommandKind::GlBegin: glBegin(c); break;
    case CommandKind::GlVertex: glVertex(c); break;
    case CommandKind::GlEnd: glEnd(&c); break;
    case CommandKind::NumPatchVertices:
        if (numbers(c)) {
            double n = c.args[0].number;
            if (n != std::floor(n) || n < 1 || n > 32)
                diags_.error(file(), c.args[0].loc, "NumPatchVertices takes a whole number from 1 to 32");
            else
                patchVertices_ = int(n);
        }
        break;
    default:
        diags_.warning(file(), c.loc, fmt::format("{} is not supported yet; line ignored", c.spelled));
        break;
    }
}

std::optional<glm::vec4> Builder::colorArgs(const Command& c) {
    std::vector<double> v;
    if (c.args.size() == 1 && c.args[0].isGroup()) {  // Color [1 0 0]
        for (const auto& i : c.args[0].items) {
            if (i.kind != Arg::Kind::Number) {
                diags_.error(file(), i.loc, fmt::format("{} takes numbers; '{}' is not a number", c.spelled, i.text));
                return std::nullopt;
            }
            v.push_back(i.number);
        }
        if (v.size() < 3 || v.size() > 4) {
            diags_.error(file(), c.loc, fmt::format("{} takes 3 or 4 numbers, got {}", c.spelled, v.size()));
            return std::nullopt;
        }
    } else {
        if (!numbers(c, 3, 4)) return std::nullopt;
        for (const auto& a : c.args) v.push_back(a.number);
    }
    return glm::vec4(v[0], v[1], v[2], v.size() > 3 ? v[3] : 1.0);
}

void Builder::ortho(const Command& c) {
    if (c.args.empty()) {  // a bare Ortho means glman's defaults
        projection_ = Projection{};
        return;
    }
    if (!numbers(c)) return;
    double l = c.args[0].number, r = c.args[1].number, b = c.args[2].number, t = c.args[3].number;
    if (l == r || b == t) {
        // glOrtho rejects this with GL_INVALID_VALUE and leaves the
        // matrix alone, so the projection already in force stays.
        diags_.warning(file(), c.loc,
                       fmt::format("degenerate Ortho {} {} {} {} ({}): OpenGL rejects it and keeps the "
                                   "current projection, {}",
                                   c.args[0].text, c.args[1].text, c.args[2].text, c.args[3].text,
                                   l == r ? "left == right" : "bottom == top", projection_.describe()));
        return;
    }
    projection_.kind = Projection::Kind::Ortho;
    projection_.ortho[0] = l;
    projection_.ortho[1] = r;
    projection_.ortho[2] = b;
    projection_.ortho[3] = t;
}

void Builder::lookAt(const Command& c) {
    if (!numbers(c)) return;
    glm::vec3 eye(num(c, 0), num(c, 1), num(c, 2));
    glm::vec3 at(num(c, 3), num(c, 4), num(c, 5));
    glm::vec3 up(num(c, 6), num(c, 7), num(c, 8));
    glm::vec3 dir = at - eye;
    if (glm::length(dir) == 0.f || glm::length(glm::cross(dir, up)) == 0.f) {
        diags_.error(file(), c.loc, "LookAt needs an eye apart from the point looked at, and an up vector "
                                    "not along the line of sight");
        return;
    }
    view_ = glm::lookAt(eye, at, up);
}

// A draw with the state in force now; its mesh is filled in by the caller.
Step Builder::drawStep(SourceLoc loc) {
    auto [w, h] = aspectSize();
    Step s;
    s.kind = Step::Kind::Draw;
    Draw& d = s.draw;
    d.program = program_;
    d.projection = projection_.matrix(w, h);
    d.modelView = view_ * model_;
    d.view = view_;
    d.color = color_;
    d.units = units_;
    for (const auto& [unit, kinds] : unitTargets_)
        for (const auto& [kind, tex] : kinds)
            if (tex != units_.at(unit)) d.otherTargets[unit].push_back(tex);
    d.lineWidth = lineWidth_;
    d.pointSize = pointSize_;
    d.flatShading = flat_;
    d.patchVertices = patchVertices_;
    d.loc = loc;
    return s;
}

// Which textures a draw may sample: the units its Program's integer
// constants name (how samplers get their units), and unit 0, where an
// unset sampler looks.
std::set<int> Builder::drawReads(const Draw& d) const {
    std::set<int> reads;
    if (d.program < 0) return reads;
    std::set<int> units = {0};
    for (const auto& u : plan_.programs[d.program].uniforms)
        if (u.form == UniformSetting::Form::Constant && u.values.size() == 1 && wholeIn(u.values[0], 0, 31))
            units.insert(int(u.values[0]));
    for (int unit : units)
        for (int tex : d.texturesOn(unit)) reads.insert(tex);
    return reads;
}

void Builder::finish() {
    // Passes that draw nothing do nothing. The first screen pass has no
    // RenderToTexture line of its own: it is known by its first draw.
    std::vector<Pass> kept;
    for (auto& p : plan_.passes) {
        if (p.steps.empty()) continue;
        for (const auto& s : p.steps)
            if (p.loc.line == 0 && s.kind == Step::Kind::Draw) p.loc = s.draw.loc;
        kept.push_back(std::move(p));
    }
    plan_.passes = std::move(kept);

    std::vector<char> flatMesh(plan_.meshes.size());  // once per mesh, not per draw
    for (size_t i = 0; i < plan_.meshes.size(); ++i) flatMesh[i] = plan_.meshes[i].flat();
    for (auto& p : plan_.passes) {
        int draws = 0;
        bool solid = false;
        for (const auto& s : p.steps) {
            if (s.kind != Step::Kind::Draw) continue;
            ++draws;
            if (!flatMesh[size_t(s.draw.mesh)]) solid = true;
            for (int t : drawReads(s.draw)) p.reads.insert(t);
        }
        // One flat quad cannot hide anything; depth only matters with more.
        p.needsDepth = solid || draws > 1;
        for (int t : p.targets) {
            plan_.textures[t].renderTarget = true;
            plan_.textures[t].needsDepth |= p.needsDepth;
            if (p.reads.count(t))
                diags_.warning(file(), p.loc, "a pass reads the texture it renders into; the result is undefined");
        }
    }
    markHiddenClears(plan_);

    // Walk back from the screen: a pass is needed when a needed pass after
    // it reads what it writes, or the user asked to see its target.
    std::set<int> wanted;
    for (int unit : options_.keepTargets) {
        auto it = plan_.finalUnits.find(unit);
        if (it != plan_.finalUnits.end()) wanted.insert(it->second);
    }
    for (auto p = plan_.passes.rbegin(); p != plan_.passes.rend(); ++p) {
        if (p->targets.empty()) {
            p->needed = true;
        } else {
            p->needed = false;
            for (int t : p->targets)
                if (wanted.count(t)) p->needed = true;
        }
        if (p->needed) wanted.insert(p->reads.begin(), p->reads.end());
    }
    plan_.maxMemoryBytes = options_.maxMemoryBytes;
    plan_.scriptBytes = script_.bytes;
    checkMemoryBudget(plan_, options_.maxMemoryBytes, diags_);
}

}  // namespace plan_detail

bool MeshDecl::flat() const {
    const ShapeRule* rule = findShapeRule(commandName(shape));
    if (!rule) return false;
    switch (rule->flatness) {
    case ShapeRule::Flatness::Always: return true;
    case ShapeRule::Flatness::Never: return false;
    case ShapeRule::Flatness::IfPointsCoplanar: {
        std::vector<glm::dvec3> p;
        p.reserve(points.size() / 3);
        for (size_t i = 0; i + 2 < points.size(); i += 3) p.emplace_back(points[i], points[i + 1], points[i + 2]);
        return coplanar(p);
    }
    }
    return false;
}

bool parseTextureFormat(const std::string& word, TextureDecl::Format& out) {
    std::string w = word;
    for (auto& ch : w) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    if (w == "RGBA8") out = TextureDecl::Format::RGBA8;
    else if (w == "RGBA16F") out = TextureDecl::Format::RGBA16F;
    else if (w == "RGBA32F") out = TextureDecl::Format::RGBA32F;
    else if (w == "R11F_G11F_B10F") out = TextureDecl::Format::R11F_G11F_B10F;
    else return false;
    return true;
}

const char* textureFormatName(TextureDecl::Format f) {
    switch (f) {
    case TextureDecl::Format::RGBA8: return "RGBA8";
    case TextureDecl::Format::RGBA16F: return "RGBA16F";
    case TextureDecl::Format::RGBA32F: return "RGBA32F";
    case TextureDecl::Format::R11F_G11F_B10F: return "R11F_G11F_B10F";
    }
    return "?";
}

bool parseTextureWrap(const std::string& word, TextureDecl::Wrap& out) {
    std::string w = word;
    for (auto& ch : w) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (w.rfind("gl_", 0) == 0) w = w.substr(3);  // GL_CLAMP_TO_EDGE, as OpenGL spells it
    if (w == "repeat") out = TextureDecl::Wrap::Repeat;
    else if (w == "clamp" || w == "clamp_to_edge") out = TextureDecl::Wrap::Clamp;
    else if (w == "mirror" || w == "mirrored_repeat") out = TextureDecl::Wrap::Mirror;
    else return false;
    return true;
}

const char* textureWrapName(TextureDecl::Wrap w) {
    switch (w) {
    case TextureDecl::Wrap::Repeat: return "repeat";
    case TextureDecl::Wrap::Clamp: return "clamp";
    case TextureDecl::Wrap::Mirror: return "mirror";
    }
    return "?";
}

bool isFloatFormat(TextureDecl::Format f) { return f != TextureDecl::Format::RGBA8; }

bool relativeSize(const std::string& word, int width, int height, int& out) {
    if (word.empty()) return false;
    char axis = char(std::tolower(static_cast<unsigned char>(word[0])));
    if (axis != 'w' && axis != 'h') return false;
    long base = axis == 'w' ? width : height;
    if (word.size() == 1) {
        out = int(base);
        return true;
    }
    char op = word[1];
    if ((op != '/' && op != '*') || word.size() < 3) return false;
    long n = 0;
    for (size_t i = 2; i < word.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(word[i])) || n > 100000) return false;
        n = n * 10 + (word[i] - '0');
    }
    if (n < 1) return false;
    long v = op == '/' ? base / n : base * n;
    out = int(std::clamp(v, 1L, 16384L));
    return true;
}

bool Plan::screenNeeded() const {
    for (const auto& p : passes)
        if (p.targets.empty()) return true;
    return false;
}

Plan buildPlan(const Script& script, const PlanOptions& options, Diagnostics& diags) {
    return plan_detail::Builder(script, options, diags).build();
}

}  // namespace glimmer
