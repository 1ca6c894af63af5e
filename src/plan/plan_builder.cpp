// Walks the commands in script order, keeping glman's state (matrices,
// colour, current shaders, texture units) and writing passes of draws.
#include <cmath>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "plan/plan.h"
#include "plan/uniform_forms.h"

namespace glimmer {
namespace {

// glman's defaults.
constexpr double kDefaultOrtho[4] = {-3, 3, -3, 3};
constexpr double kDefaultFov = 50;

struct Projection {
    enum class Kind { Ortho, Perspective } kind = Kind::Ortho;
    double ortho[4] = {kDefaultOrtho[0], kDefaultOrtho[1], kDefaultOrtho[2], kDefaultOrtho[3]};
    double fov = kDefaultFov;

    std::string describe() const {
        if (kind == Kind::Perspective) return fmt::format("Perspective {:g}", fov);
        return fmt::format("Ortho {:g} {:g} {:g} {:g}", ortho[0], ortho[1], ortho[2], ortho[3]);
    }

    // The viewport's aspect ratio widens one axis, as glman's reshape does,
    // so a square stays square in a wide window.
    glm::mat4 matrix(int w, int h) const {
        double aspect = (w > 0 && h > 0) ? double(w) / double(h) : 1.0;
        switch (kind) {
        case Kind::Perspective:
            return glm::perspective(glm::radians(float(fov)), float(aspect), 0.1f, 1000.f);
        case Kind::Ortho: {
            double l = ortho[0], r = ortho[1], b = ortho[2], t = ortho[3];
            double cx = (l + r) / 2, cy = (b + t) / 2, hx = (r - l) / 2, hy = (t - b) / 2;
            if (aspect >= 1) hx *= aspect; else hy /= aspect;
            return glm::ortho(float(cx - hx), float(cx + hx), float(cy - hy), float(cy + hy), -1000.f, 1000.f);
        }
        }
        return glm::mat4(1.f);
    }
};

class Builder {
public:
    Builder(const Script& script, const PlanOptions& options, Diagnostics& diags)
        : script_(script), options_(options), diags_(diags) {}

    Plan build() {
        plan_.scriptFile = script_.file;
        // The size must be known before any matrix is computed: --size wins,
        // then the first WindowSize, then glman's 600x600.
        for (const auto& c : script_.commands) {
            if (c.kind == CommandKind::WindowSize) {
                if (numbers(c, 2, 2)) {
                    plan_.width = int(c.args[0].number);
                    plan_.height = int(c.args[1].number);
                    if (plan_.width < 1 || plan_.height < 1 || plan_.width > 16384 || plan_.height > 16384) {
                        diags_.error(file(), c.loc, "WindowSize must be between 1 and 16384 pixels each way");
                        plan_.width = plan_.height = 600;
                    }
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
        plan_.finalUnits = units_;
        finish();
        return std::move(plan_);
    }

private:
    const std::string& file() const { return script_.file; }

    // Checks that a command has between lo and hi arguments, all numbers.
    bool numbers(const Command& c, size_t lo, size_t hi) {
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
        }
        return true;
    }

    double num(const Command& c, size_t i, double fallback) const {
        return i < c.args.size() ? c.args[i].number : fallback;
    }

    Pass& pass() { return plan_.passes.back(); }
    // The aspect ratio the projection keeps. Only the screen is widened, as
    // glman's window reshape does; a quad drawn to cover a texture target
    // must cover it exactly, whatever the texture's shape.
    std::pair<int, int> aspectSize() const {
        if (plan_.passes.back().targets.empty()) return {plan_.width, plan_.height};
        return {1, 1};
    }

    void command(const Command& c) {
        switch (c.kind) {
        case CommandKind::WindowSize: numbers(c, 2, 2); break;  // read before the walk
        case CommandKind::Ortho: ortho(c); break;
        case CommandKind::Perspective:
            if (numbers(c, 0, 1)) {
                projection_.kind = Projection::Kind::Perspective;
                projection_.fov = num(c, 0, kDefaultFov);
                if (!(projection_.fov > 0 && projection_.fov < 180)) {
                    diags_.error(file(), c.loc, "Perspective's field of view must be between 0 and 180 degrees");
                    projection_.fov = kDefaultFov;
                }
            }
            break;
        case CommandKind::LookAt: lookAt(c); break;
        case CommandKind::Translate:
            if (numbers(c, 2, 3)) model_ = glm::translate(model_, glm::vec3(num(c, 0, 0), num(c, 1, 0), num(c, 2, 0)));
            break;
        case CommandKind::Rotate:
            if (numbers(c, 4, 4)) {
                glm::vec3 axis(num(c, 1, 0), num(c, 2, 0), num(c, 3, 0));
                if (glm::length(axis) == 0.f)
                    diags_.warning(file(), c.loc, "Rotate about a zero axis does nothing");
                else
                    model_ = glm::rotate(model_, glm::radians(float(num(c, 0, 0))), axis);
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
            if (numbers(c, 1, 1)) lineWidth_ = float(num(c, 0, 1));
            break;
        case CommandKind::PointSize:
            if (numbers(c, 1, 1)) pointSize_ = float(num(c, 0, 1));
            break;
        case CommandKind::Flat: flat_ = true; break;
        case CommandKind::Smooth: flat_ = false; break;
        case CommandKind::Timer:
            if (numbers(c, 0, 1)) {
                double t = num(c, 0, 10);
                if (t > 0) plan_.timerPeriod = t;
                else diags_.error(file(), c.loc, "Timer's period must be more than 0 seconds");
            }
            break;
        case CommandKind::MessageBox: break;  // glman shows the text in a dialog; headless has no one to show it to
        case CommandKind::Gstap: gstap_ = true; break;
        case CommandKind::Texture2D: texture2D(c); break;
        case CommandKind::RenderToTexture: renderToTexture(c); break;
        case CommandKind::Vertex: stage(c, ShaderStage::Kind::Vertex); break;
        case CommandKind::Fragment: stage(c, ShaderStage::Kind::Fragment); break;
        case CommandKind::Geometry: stage(c, ShaderStage::Kind::Geometry); break;
        case CommandKind::Program: program(c); break;
        case CommandKind::QuadXY:
        case CommandKind::QuadXZ:
        case CommandKind::QuadYZ:
            if (numbers(c, 2, 4)) mesh(c, {num(c, 0, 0), num(c, 1, 1), num(c, 2, 1), num(c, 3, 1)});
            break;
        case CommandKind::Sphere:
            if (numbers(c, 0, 3)) mesh(c, {num(c, 0, 1), num(c, 1, 60), num(c, 2, 60)});
            break;
        case CommandKind::Torus:
            if (numbers(c, 0, 4)) mesh(c, {num(c, 0, 1), num(c, 1, .5), num(c, 2, 20), num(c, 3, 40)});
            break;
        case CommandKind::Box:
            if (numbers(c, 0, 3)) {
                double dx = num(c, 0, 2);
                mesh(c, {dx, num(c, 1, c.args.size() == 1 ? dx : 2), num(c, 2, c.args.size() == 1 ? dx : 2)});
            }
            break;
        case CommandKind::Obj: obj(c); break;
        default:
            diags_.warning(file(), c.loc, fmt::format("{} is not supported yet; line ignored", c.spelled));
            break;
        }
    }

    std::optional<glm::vec4> colorArgs(const Command& c) {
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

    void ortho(const Command& c) {
        if (c.args.empty()) {  // a bare Ortho means glman's defaults
            projection_ = Projection{};
            return;
        }
        if (!numbers(c, 4, 4)) return;
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

    void lookAt(const Command& c) {
        if (!numbers(c, 9, 9)) return;
        glm::vec3 eye(num(c, 0, 0), num(c, 1, 0), num(c, 2, 0));
        glm::vec3 at(num(c, 3, 0), num(c, 4, 0), num(c, 5, 0));
        glm::vec3 up(num(c, 6, 0), num(c, 7, 1), num(c, 8, 0));
        glm::vec3 dir = at - eye;
        if (glm::length(dir) == 0.f || glm::length(glm::cross(dir, up)) == 0.f) {
            diags_.error(file(), c.loc, "LookAt needs an eye apart from the point looked at, and an up vector "
                                        "not along the line of sight");
            return;
        }
        view_ = glm::lookAt(eye, at, up);
    }

    int unitArg(const Command& c, const Arg& a) {
        if (a.kind != Arg::Kind::Number || a.number != std::floor(a.number) || a.number < 0 || a.number > 31) {
            diags_.error(file(), a.loc, fmt::format("{} needs a texture unit from 0 to 31, not '{}'", c.spelled, a.text));
            return -1;
        }
        return int(a.number);
    }

    void texture2D(const Command& c) {
        if (c.args.empty()) {
            diags_.error(file(), c.loc, "Texture2D needs a unit and a file, or a unit, a width and a height");
            return;
        }
        int unit = unitArg(c, c.args[0]);
        if (unit < 0) return;
        TextureDecl t;
        t.loc = c.loc;
        if (c.args.size() == 2 && c.args[1].kind == Arg::Kind::Word) {
            t.source = TextureDecl::Source::File;
            t.shown = c.args[1].text;
            std::vector<std::string> tried;
            t.path = resolveFile(file(), t.shown, options_.includeDirs, &tried);
            if (t.path.empty()) {
                notFound(c.args[1].loc, "texture", t.shown, tried);
                return;
            }
            // Scripts re-bind the same file many times (one skybox face per
            // quad): share one texture per file.
            for (size_t i = 0; i < plan_.textures.size(); ++i) {
                if (plan_.textures[i].source == TextureDecl::Source::File && plan_.textures[i].path == t.path) {
                    units_[unit] = int(i);
                    return;
                }
            }
        } else if (c.args.size() == 3 && c.args[1].kind == Arg::Kind::Number && c.args[2].kind == Arg::Kind::Number) {
            t.width = int(c.args[1].number);
            t.height = int(c.args[2].number);
            if (t.width < 1 || t.height < 1 || t.width > 16384 || t.height > 16384) {
                diags_.error(file(), c.args[1].loc, "a texture's size must be between 1 and 16384 each way");
                return;
            }
        } else {
            diags_.error(file(), c.loc, "Texture2D needs a unit and a file, or a unit, a width and a height");
            return;
        }
        plan_.textures.push_back(t);
        units_[unit] = int(plan_.textures.size()) - 1;
    }

    void notFound(SourceLoc loc, const char* what, const std::string& name, const std::vector<std::string>& tried) {
        std::string where;
        for (const auto& d : tried) where += (where.empty() ? "" : ", ") + d;
        diags_.error(file(), loc, fmt::format("cannot find {} '{}' (looked in {})", what, name, where));
    }

    void renderToTexture(const Command& c) {
        Pass p;
        p.loc = c.loc;
        for (const auto& a : c.args) {
            int unit = unitArg(c, a);
            if (unit < 0) return;
            auto it = units_.find(unit);
            if (it == units_.end()) {
                diags_.error(file(), a.loc, fmt::format("no texture on unit {} to render into; "
                                                        "give it one first with Texture2D {} width height", unit, unit));
                return;
            }
            const TextureDecl& t = plan_.textures[it->second];
            // An image's size is only known once it is loaded, so this check
            // comes before the size check, which would otherwise misreport it.
            if (t.source == TextureDecl::Source::File) {
                diags_.error(file(), a.loc, fmt::format("unit {} holds the image '{}'; render into an empty "
                                                        "texture made with Texture2D {} width height", unit, t.shown, unit));
                return;
            }
            if (!p.targets.empty()) {
                const TextureDecl& first = plan_.textures[p.targets.front()];
                if (t.width != first.width || t.height != first.height) {
                    diags_.error(file(), a.loc, "all textures rendered into at once must have the same size");
                    return;
                }
            }
            p.targets.push_back(it->second);
        }
        plan_.passes.push_back(std::move(p));
    }

    void stage(const Command& c, ShaderStage::Kind kind) {
        stages_.erase(kind);
        if (c.args.empty()) return;  // no argument un-sets the stage
        if (c.args.size() != 1 || c.args[0].kind != Arg::Kind::Word) {
            diags_.error(file(), c.loc, fmt::format("{} takes one shader file name", c.spelled));
            return;
        }
        ShaderStage s;
        s.kind = kind;
        s.shown = c.args[0].text;
        s.loc = c.args[0].loc;
        std::vector<std::string> tried;
        s.path = resolveFile(file(), s.shown, options_.includeDirs, &tried);
        if (s.path.empty()) {
            notFound(c.args[0].loc, "shader", s.shown, tried);
            return;
        }
        stages_[kind] = s;
    }

    void program(const Command& c) {
        if (c.args.empty() || c.args[0].kind != Arg::Kind::Word) {
            diags_.error(file(), c.loc, "Program needs a name");
            return;
        }
        ProgramDecl p;
        p.name = c.args[0].text;
        p.loc = c.loc;
        p.gstap = gstap_;
        for (const auto& [kind, s] : stages_) p.stages.push_back(s);
        if (p.stages.empty())
            diags_.warning(file(), c.loc, fmt::format("Program {} has no shaders; set Vertex and Fragment first", p.name));
        p.uniforms = parseUniformSettings(c, 1, file(), diags_);
        bool fixedFunction = p.stages.empty();
        plan_.programs.push_back(std::move(p));
        // A Program without shaders draws with OpenGL's fixed function.
        program_ = fixedFunction ? -1 : int(plan_.programs.size()) - 1;
    }

    void obj(const Command& c) {
        if (c.args.size() != 1 || c.args[0].kind != Arg::Kind::Word) {
            diags_.error(file(), c.loc, "Obj takes one .obj file name");
            return;
        }
        std::vector<std::string> tried;
        std::string path = resolveFile(file(), c.args[0].text, options_.includeDirs, &tried);
        if (path.empty()) {
            notFound(c.args[0].loc, "model", c.args[0].text, tried);
            return;
        }
        mesh(c, {}, path);
    }

    void mesh(const Command& c, std::vector<double> params, const std::string& path = {}) {
        MeshDecl m;
        m.shape = c.kind;
        m.params = std::move(params);
        m.path = path;
        m.loc = c.loc;
        auto [it, added] = meshIndex_.try_emplace(m, int(plan_.meshes.size()));
        if (added) plan_.meshes.push_back(m);

        auto [w, h] = aspectSize();
        Step s;
        s.kind = Step::Kind::Draw;
        Draw& d = s.draw;
        d.mesh = it->second;
        d.program = program_;
        d.projection = projection_.matrix(w, h);
        d.modelView = view_ * model_;
        d.view = view_;
        d.color = color_;
        d.units = units_;
        d.lineWidth = lineWidth_;
        d.pointSize = pointSize_;
        d.flatShading = flat_;
        d.loc = c.loc;
        pass().steps.push_back(s);
    }

    // Which textures a draw may sample: the units its Program's integer
    // constants name (how samplers get their units), and unit 0, where an
    // unset sampler looks.
    std::set<int> drawReads(const Draw& d) const {
        std::set<int> reads;
        if (d.program < 0) return reads;
        std::set<int> units = {0};
        for (const auto& u : plan_.programs[d.program].uniforms)
            if (u.form == UniformSetting::Form::Constant && u.values.size() == 1) units.insert(int(u.values[0]));
        for (int unit : units) {
            auto it = d.units.find(unit);
            if (it != d.units.end()) reads.insert(it->second);
        }
        return reads;
    }

    void finish() {
        // Passes that draw nothing do nothing.
        std::vector<Pass> kept;
        for (auto& p : plan_.passes)
            if (!p.steps.empty()) kept.push_back(std::move(p));
        plan_.passes = std::move(kept);

        for (auto& p : plan_.passes) {
            int draws = 0;
            bool solid = false;
            for (const auto& s : p.steps) {
                if (s.kind != Step::Kind::Draw) continue;
                ++draws;
                CommandKind shape = plan_.meshes[s.draw.mesh].shape;
                if (shape != CommandKind::QuadXY && shape != CommandKind::QuadXZ && shape != CommandKind::QuadYZ)
                    solid = true;
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
    }

    const Script& script_;
    const PlanOptions& options_;
    Diagnostics& diags_;
    Plan plan_;

    Projection projection_;
    glm::mat4 view_{1.f};  // without a LookAt the eye sits at the origin looking down -Z
    glm::mat4 model_{1.f};
    std::vector<glm::mat4> stack_;
    glm::vec4 background_{0.f, 0.f, 0.f, 1.f};
    glm::vec4 color_{1.f};
    float lineWidth_ = 1.f, pointSize_ = 1.f;
    bool flat_ = false;
    bool gstap_ = false;
    std::map<int, int> units_;
    std::map<ShaderStage::Kind, ShaderStage> stages_;
    int program_ = -1;
    std::map<MeshDecl, int> meshIndex_;
};

}  // namespace

bool Plan::screenNeeded() const {
    for (const auto& p : passes)
        if (p.targets.empty()) return true;
    return false;
}

Plan buildPlan(const Script& script, const PlanOptions& options, Diagnostics& diags) {
    return Builder(script, options, diags).build();
}

}  // namespace glimmer
