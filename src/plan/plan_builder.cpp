// Walks the commands in script order, keeping glman's state (matrices,
// colour, current shaders, texture units) and writing passes of draws.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/mesh.h"
#include "plan/limits.h"
#include "plan/plan.h"
#include "plan/memory_budget.h"
#include "plan/sandbox.h"
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
            if (!inFloatRange(a.number)) {
                diags_.error(file(), a.loc, fmt::format("{}: '{}' is out of range (at most 1e30 either way)", c.spelled, a.text));
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
        if (imm_ && c.kind != CommandKind::GlVertex && c.kind != CommandKind::GlEnd && c.kind != CommandKind::GlBegin)
            diags_.warning(file(), c.loc, fmt::format("only glVertex belongs between glBegin (line {}) and glEnd; {} "
                                                      "acts here, on what is drawn after it, not on this glBegin",
                                                      imm_->step.draw.loc.line, c.spelled));
        switch (c.kind) {
        case CommandKind::WindowSize:  // read before the walk; checked here
            if (numbers(c, 2, 2) && (!wholeIn(c.args[0].number, 1, 16384) || !wholeIn(c.args[1].number, 1, 16384)))
                diags_.error(file(), c.loc, "WindowSize must be between 1 and 16384 pixels each way");
            break;
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
        case CommandKind::Noise2D:
        case CommandKind::Noise3D: noiseRes(c); break;
        case CommandKind::Texture2D: texture2D(c); break;
        case CommandKind::Texture3D: texture3D(c); break;
        case CommandKind::CubeMap: cubeMap(c); break;
        case CommandKind::RenderToTexture: renderToTexture(c); break;
        case CommandKind::Vertex: stage(c, ShaderStage::Kind::Vertex); break;
        case CommandKind::Fragment: stage(c, ShaderStage::Kind::Fragment); break;
        case CommandKind::Geometry: stage(c, ShaderStage::Kind::Geometry); break;
        case CommandKind::TessControl: stage(c, ShaderStage::Kind::TessControl); break;
        case CommandKind::TessEvaluation: stage(c, ShaderStage::Kind::TessEvaluation); break;
        case CommandKind::Program: program(c); break;
        case CommandKind::QuadXY:
        case CommandKind::QuadXZ:
        case CommandKind::QuadYZ:
            if (numbers(c, 2, 4) && shapeCounts(c, 2, 1)) mesh(c, {num(c, 0, 0), num(c, 1, 1), num(c, 2, 1), num(c, 3, 1)});
            break;
        case CommandKind::Sphere:
        case CommandKind::WireSphere:
            if (numbers(c, 0, 3) && shapeCounts(c, 1, 2)) mesh(c, {num(c, 0, 1), num(c, 1, 60), num(c, 2, 60)});
            break;
        case CommandKind::Torus:
        case CommandKind::WireTorus:
            if (numbers(c, 0, 4) && shapeCounts(c, 2, 3)) mesh(c, {num(c, 0, 1), num(c, 1, .5), num(c, 2, 20), num(c, 3, 40)});
            break;
        case CommandKind::Box:
        case CommandKind::WireBox:
            if (numbers(c, 0, 3)) {
                double dx = num(c, 0, 2);
                mesh(c, {dx, num(c, 1, c.args.size() == 1 ? dx : 2), num(c, 2, c.args.size() == 1 ? dx : 2)});
            }
            break;
        case CommandKind::Cylinder:
        case CommandKind::WireCylinder:
        case CommandKind::Cone:
        case CommandKind::WireCone:
            if (numbers(c, 0, 3) && positive(c, 2)) mesh(c, {num(c, 0, 1), num(c, 1, 1), num(c, 2, 40)});
            break;
        case CommandKind::DiskXY:
            if (numbers(c, 0, 2) && positive(c, 1)) mesh(c, {num(c, 0, 1), num(c, 1, 40)});
            break;
        case CommandKind::Teapot:
        case CommandKind::WireTeapot:
            if (numbers(c, 0, 2) && positive(c, 1)) mesh(c, {num(c, 0, 1), num(c, 1, 10)});
            break;
        case CommandKind::QuadBox:
            if (numbers(c, 0, 1)) mesh(c, {num(c, 0, 1)});
            break;
        case CommandKind::PointCloud:
            // glman-like: `PointCloud [count [size]]`, count points in [-size, size]^3.
            if (numbers(c, 0, 2) && countArg(c, 0, 1000000)) mesh(c, {num(c, 0, 1000), num(c, 1, 1)});
            break;
        case CommandKind::JitterCloud:
            // `JitterCloud [n [size [jitter]]]`: an n^3 grid filling [-size, size]^3, each point jittered.
            if (numbers(c, 0, 3) && countArg(c, 0, 100)) mesh(c, {num(c, 0, 10), num(c, 1, 1), num(c, 2, .5)});
            break;
        case CommandKind::Obj:
        case CommandKind::ObjAdj:
        case CommandKind::WireObj: obj(c); break;
        case CommandKind::Triangles: pointsMesh(c, 3); break;
        case CommandKind::LinesAdjacency: pointsMesh(c, 4); break;
        case CommandKind::GlBegin: glBegin(c); break;
        case CommandKind::GlVertex: glVertex(c); break;
        case CommandKind::GlEnd: glEnd(&c); break;
        case CommandKind::NumPatchVertices:
            if (numbers(c, 1, 1)) {
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

    // Argument `i`, when given, must be a whole number of at least 3 (slices, subdivisions: 1).
    bool positive(const Command& c, size_t i) {
        if (i >= c.args.size()) return true;
        double v = c.args[i].number;
        double lo = c.kind == CommandKind::Teapot || c.kind == CommandKind::WireTeapot ? 1 : 3;
        double hi = lo == 1 ? kMaxTeapotSubdivisions : kMaxShapeCount;  // 32 patches of (n+1)^2 vertices
        if (!wholeIn(v, lo, hi)) {
            diags_.error(file(), c.args[i].loc, fmt::format("{}'s {} must be a whole number from {} to {}", c.spelled,
                                                            lo == 1 ? "subdivisions" : "slices", lo, hi));
            return false;
        }
        return true;
    }

    // Subdivision counts from argument `first` on (QuadXY's nx ny, Sphere's
    // slices stacks, Torus's sides rings): whole numbers from `lo` to
    // kMaxShapeCount, checked before anything converts them.
    bool shapeCounts(const Command& c, size_t first, double lo) {
        for (size_t i = first; i < c.args.size(); ++i) {
            if (!wholeIn(c.args[i].number, lo, kMaxShapeCount)) {
                diags_.error(file(), c.args[i].loc, fmt::format("{}'s counts must be whole numbers from {} to {}; not '{}'",
                                                                c.spelled, lo, kMaxShapeCount, c.args[i].text));
                return false;
            }
        }
        return true;
    }

    bool countArg(const Command& c, size_t i, double hi) {
        if (i >= c.args.size()) return true;
        double v = c.args[i].number;
        if (v != std::floor(v) || v < 1 || v > hi) {
            diags_.error(file(), c.args[i].loc, fmt::format("{}'s count must be a whole number from 1 to {}", c.spelled, hi));
            return false;
        }
        return true;
    }

    void noiseRes(const Command& c) {
        bool two = c.kind == CommandKind::Noise2D;
        if (!numbers(c, 0, 1)) return;
        double res = num(c, 0, 64);
        double hi = two ? 4096 : 512;
        if (res != std::floor(res) || res < 1 || res > hi) {
            diags_.error(file(), c.loc, fmt::format("{}'s resolution must be a whole number from 1 to {}", c.spelled, hi));
            return;
        }
        (two ? plan_.noise2DRes : plan_.noise3DRes) = int(res);
    }

    // One point from an `[x y z]` group (a 2-number group lies at z = 0).
    std::optional<glm::dvec3> point(const Command& c, const Arg& a) {
        if (a.kind != Arg::Kind::Array || a.items.size() < 2 || a.items.size() > 3) {
            diags_.error(file(), a.loc, fmt::format("{} takes points written [x y z]; '{}' is not one", c.spelled,
                                                    a.isGroup() ? std::string("a group of ") + std::to_string(a.items.size()) : a.text));
            return std::nullopt;
        }
        for (const auto& i : a.items)
            if (i.kind != Arg::Kind::Number || !inFloatRange(i.number)) {
                diags_.error(file(), i.loc, fmt::format("{} takes numbers of at most 1e30; '{}' is not one", c.spelled, i.text));
                return std::nullopt;
            }
        return glm::dvec3(a.items[0].number, a.items[1].number, a.items.size() > 2 ? a.items[2].number : 0.0);
    }

    // Triangles (3 points a primitive), LinesAdjacency (4).
    void pointsMesh(const Command& c, size_t per) {
        std::vector<double> pts;
        for (const auto& a : c.args) {
            auto p = point(c, a);
            if (!p) return;
            pts.insert(pts.end(), {p->x, p->y, p->z});
        }
        size_t n = pts.size() / 3;
        if (n < per) {
            diags_.error(file(), c.loc, fmt::format("{} needs {} points [x y z], got {}", c.spelled, per, n));
            return;
        }
        if (n % per)
            diags_.warning(file(), c.args[n - n % per].loc,
                           fmt::format("{} takes points in groups of {}; the last {} ignored", c.spelled, per,
                                       n % per == 1 ? std::string("one is") : std::to_string(n % per) + " are"));
        mesh(c, {}, {}, std::move(pts));
    }

    void glBegin(const Command& c) {
        if (imm_) {
            diags_.warning(file(), c.loc, fmt::format("glBegin inside the glBegin of line {}; that one ends here",
                                                      imm_->step.draw.loc.line));
            glEnd(nullptr);
        }
        Immediate b;
        b.step = drawStep(c.loc);
        std::optional<ImmediatePrimitive> prim;
        if (c.args.size() == 1 && c.args[0].kind == Arg::Kind::Word) prim = parseImmediatePrimitive(c.args[0].text);
        if (!prim) {
            diags_.error(file(), c.args.empty() ? c.loc : c.args[0].loc,
                         fmt::format("glBegin takes one primitive: gl_points, gl_lines, gl_line_strip, gl_line_loop, "
                                     "gl_triangles, gl_triangle_strip, gl_triangle_fan, gl_quads, gl_quad_strip, "
                                     "gl_polygon or gl_patches{}",
                                     c.args.empty() ? std::string() : "; not '" + c.args[0].text + "'"));
            b.valid = false;  // its glVertex lines are swallowed up to the glEnd
        } else {
            b.primitive = *prim;
        }
        imm_ = std::move(b);
    }

    void glVertex(const Command& c) {
        if (!imm_) {
            diags_.warning(file(), c.loc, "glVertex outside glBegin ... glEnd; ignored");
            return;
        }
        if (!numbers(c, 2, 4)) return;
        double w = num(c, 3, 1);
        if (w == 0) {
            diags_.error(file(), c.args[3].loc, "glVertex with w = 0 is a point at infinity; ignored");
            return;
        }
        imm_->points.insert(imm_->points.end(), {num(c, 0, 0) / w, num(c, 1, 0) / w, num(c, 2, 0) / w});
    }

    // `end` is null when the block is closed by a new glBegin or the end of the script.
    void glEnd(const Command* end) {
        if (!imm_) {
            if (end) diags_.warning(file(), end->loc, "glEnd without glBegin; ignored");
            return;
        }
        Immediate b = std::move(*imm_);
        imm_.reset();
        if (!b.valid) return;
        if (b.points.empty()) {
            diags_.warning(file(), b.step.draw.loc, "glBegin ... glEnd with no glVertex draws nothing");
            return;
        }
        if (!countDraw(b.step.draw.loc)) return;
        MeshDecl m;
        m.shape = CommandKind::GlBegin;
        m.params = {double(int(b.primitive))};
        m.points = std::move(b.points);
        m.loc = b.step.draw.loc;
        b.step.draw.mesh = meshIndex(m);
        pass().steps.push_back(b.step);
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

    // Finds a texture file; false (reported) when it is not there.
    bool textureFile(const Arg& a, std::string& path) {
        path = findFile(a, "texture");
        return !path.empty();
    }

    // Resolves a file the script names, as glman would or, under --sandbox,
    // only inside the sandbox; empty (reported) when it cannot be used.
    std::string findFile(const Arg& a, const char* what) {
        std::vector<std::string> tried;
        if (!options_.sandbox) {
            std::string path = resolveFile(file(), a.text, options_.includeDirs, &tried);
            if (path.empty()) notFound(a.loc, what, a.text, tried);
            return path;
        }
        std::string path, why;
        switch (resolveSandboxed(file(), a.text, options_.includeDirs, path, tried, why)) {
        case SandboxLookup::Found: return path;
        case SandboxLookup::NotFound: notFound(a.loc, what, a.text, tried); break;
        case SandboxLookup::Outside:
            diags_.error(file(), a.loc, fmt::format("{} '{}' is outside the sandbox ({}); --sandbox reads only files "
                                                    "in the script's folder and -I folders", what, a.text, why));
            break;
        }
        return {};
    }

    // Binds `t` to `unit` where the command stands. Scripts re-bind the same
    // file many times (one skybox face per quad): one texture per file (per
    // six files for a cube map) is shared.
    void bindTexture(int unit, TextureDecl t) {
        if (t.source == TextureDecl::Source::File) {
            for (size_t i = 0; i < plan_.textures.size(); ++i) {
                const TextureDecl& o = plan_.textures[i];
                if (o.source == TextureDecl::Source::File && o.kind == t.kind && o.path == t.path &&
                    o.facePaths == t.facePaths) {
                    units_[unit] = int(i);
                    return;
                }
            }
        }
        plan_.textures.push_back(std::move(t));
        units_[unit] = int(plan_.textures.size()) - 1;
    }

    // Checks `w h [d]` of an empty texture.
    bool sizeArgs(const Command& c, size_t first, size_t n) {
        for (size_t i = first; i < first + n; ++i) {
            double v = c.args[i].number;
            double hi = n == 3 ? 2048 : 16384;
            if (v != std::floor(v) || v < 1 || v > hi) {
                diags_.error(file(), c.args[i].loc, fmt::format("a texture's size must be between 1 and {} each way", hi));
                return false;
            }
        }
        return true;
    }

    bool allNumbers(const Command& c, size_t first) {
        for (size_t i = first; i < c.args.size(); ++i)
            if (c.args[i].kind != Arg::Kind::Number) return false;
        return true;
    }

    // What Texture2D and Texture3D share: the unit, and the file form
    // (`unit file`). Returns the unit, or -1 after an error; `isFile` says
    // whether the file form was read into `t`.
    int textureHead(const Command& c, TextureDecl::Kind kind, const char* usage, TextureDecl& t, bool& isFile) {
        isFile = false;
        if (c.args.empty()) {
            diags_.error(file(), c.loc, usage);
            return -1;
        }
        int unit = unitArg(c, c.args[0]);
        if (unit < 0) return -1;
        t.kind = kind;
        t.loc = c.loc;
        if (c.args.size() == 2 && c.args[1].kind == Arg::Kind::Word) {
            isFile = true;
            t.source = TextureDecl::Source::File;
            t.shown = c.args[1].text;
            if (!textureFile(c.args[1], t.path)) return -1;
        }
        return unit;
    }

    void texture2D(const Command& c) {
        const char* usage = "Texture2D needs a unit and a file, or a unit, a width and a height";
        TextureDecl t;
        bool isFile = false;
        int unit = textureHead(c, TextureDecl::Kind::Tex2D, usage, t, isFile);
        if (unit < 0) return;
        if (isFile) {
            // the file form is complete
        } else if (c.args.size() >= 3 && c.args.size() <= 5) {
            // unit W H [FORMAT] [mips]; W and H numbers or relative to the output.
            if (!targetSize(c.args[1], t.width) || !targetSize(c.args[2], t.height)) return;
            for (size_t i = 3; i < c.args.size(); ++i) {
                const Arg& a = c.args[i];
                std::string word = a.text;
                for (auto& ch : word) ch = char(std::tolower(static_cast<unsigned char>(ch)));
                if (a.kind == Arg::Kind::Word && word == "mips" && !t.mips) {
                    t.mips = true;
                } else if (a.kind == Arg::Kind::Word && i == 3 && parseTextureFormat(a.text, t.format)) {
                } else {
                    diags_.error(file(), a.loc, fmt::format("'{}' is not a texture format (RGBA8, RGBA16F, RGBA32F, "
                                                            "R11F_G11F_B10F) or 'mips'", a.text));
                    return;
                }
            }
        } else {
            diags_.error(file(), c.loc, usage);
            return;
        }
        bindTexture(unit, std::move(t));
    }

    // A render target's width or height: a whole number, or relative to
    // the output ("w/2") so a chain of targets follows the window.
    bool targetSize(const Arg& a, int& out) {
        if (a.kind == Arg::Kind::Number) {
            if (a.number != std::floor(a.number) || a.number < 1 || a.number > 16384) {
                diags_.error(file(), a.loc, "a texture's size must be between 1 and 16384 each way");
                return false;
            }
            out = int(a.number);
            return true;
        }
        if (a.kind == Arg::Kind::Word && relativeSize(a.text, plan_.width, plan_.height, out)) return true;
        diags_.error(file(), a.loc, fmt::format("'{}' is not a size: write a number, or w, h, w/2, h*2 ... "
                                                "relative to the output", a.text));
        return false;
    }

    void texture3D(const Command& c) {
        const char* usage = "Texture3D needs a unit and a raw .tex file, or a unit, a width, a height and a depth";
        TextureDecl t;
        bool isFile = false;
        int unit = textureHead(c, TextureDecl::Kind::Tex3D, usage, t, isFile);
        if (unit < 0) return;
        if (isFile) {
            // the file form is complete
        } else if (c.args.size() == 4 && allNumbers(c, 1)) {
            if (!sizeArgs(c, 1, 3)) return;
            t.width = int(c.args[1].number);
            t.height = int(c.args[2].number);
            t.depth = int(c.args[3].number);
        } else {
            diags_.error(file(), c.loc, usage);
            return;
        }
        bindTexture(unit, std::move(t));
    }

    void cubeMap(const Command& c) {
        if (c.args.size() != 7) {
            diags_.error(file(), c.loc, fmt::format("CubeMap needs a unit and six files, +x -x +y -y +z -z; got {} "
                                                    "argument{}", c.args.size(), c.args.size() == 1 ? "" : "s"));
            return;
        }
        int unit = unitArg(c, c.args[0]);
        if (unit < 0) return;
        TextureDecl t;
        t.kind = TextureDecl::Kind::Cube;
        t.source = TextureDecl::Source::File;
        t.loc = c.loc;
        for (size_t i = 1; i < 7; ++i) {
            if (c.args[i].kind != Arg::Kind::Word) {
                diags_.error(file(), c.args[i].loc, fmt::format("CubeMap needs six file names; '{}' is not one",
                                                                c.args[i].text));
                return;
            }
            std::string path;
            if (!textureFile(c.args[i], path)) return;
            t.facePaths.push_back(path);
            t.faceShown.push_back(c.args[i].text);
        }
        t.path = t.facePaths[0];
        t.shown = t.faceShown[0];
        bindTexture(unit, std::move(t));
    }

    void notFound(SourceLoc loc, const char* what, const std::string& name, const std::vector<std::string>& tried) {
        std::string where;
        for (const auto& d : tried) where += (where.empty() ? "" : ", ") + d;
        diags_.error(file(), loc, fmt::format("cannot find {} '{}' (looked in {})", what, name, where));
    }

    void renderToTexture(const Command& c) {
        if (plan_.passes.size() > kMaxPasses) {
            if (plan_.passes.size() == kMaxPasses + 1)
                diags_.error(file(), c.loc, fmt::format("more than {} RenderToTexture passes", kMaxPasses));
            plan_.passes.push_back(Pass{});  // counted once, drawn never
            return;
        }
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
            if (t.kind != TextureDecl::Kind::Tex2D) {
                diags_.error(file(), a.loc, fmt::format("unit {} holds a {}; render into an empty texture made with "
                                                        "Texture2D {} width height", unit,
                                                        t.kind == TextureDecl::Kind::Cube ? "cube map" : "3-D texture", unit));
                return;
            }
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
        s.path = findFile(c.args[0], "shader");
        if (s.path.empty()) return;
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
            diags_.error(file(), c.loc, fmt::format("{} takes one .obj file name", c.spelled));
            return;
        }
        std::string path = findFile(c.args[0], "model");
        if (path.empty()) return;
        mesh(c, {}, path);
    }

    int meshIndex(const MeshDecl& m) {
        auto [it, added] = meshIndex_.try_emplace(m, int(plan_.meshes.size()));
        if (added) plan_.meshes.push_back(m);
        return it->second;
    }

    // Counts a draw; false (reported once) past kMaxDraws.
    bool countDraw(SourceLoc loc) {
        if (++draws_ <= kMaxDraws) return true;
        if (draws_ == kMaxDraws + 1)
            diags_.error(file(), loc, fmt::format("more than {} draws; this one and those after it are not drawn", kMaxDraws));
        return false;
    }

    // A draw with the state in force now; its mesh is filled in by the caller.
    Step drawStep(SourceLoc loc) {
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
        d.lineWidth = lineWidth_;
        d.pointSize = pointSize_;
        d.flatShading = flat_;
        d.patchVertices = patchVertices_;
        d.loc = loc;
        return s;
    }

    void mesh(const Command& c, std::vector<double> params, const std::string& path = {},
              std::vector<double> points = {}) {
        if (!countDraw(c.loc)) return;
        MeshDecl m;
        m.shape = c.kind;
        m.params = std::move(params);
        m.points = std::move(points);
        m.path = path;
        m.loc = c.loc;
        Step s = drawStep(c.loc);
        s.draw.mesh = meshIndex(m);
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
            if (u.form == UniformSetting::Form::Constant && u.values.size() == 1 && wholeIn(u.values[0], 0, 31))
                units.insert(int(u.values[0]));
        for (int unit : units) {
            auto it = d.units.find(unit);
            if (it != d.units.end()) reads.insert(it->second);
        }
        return reads;
    }

    void finish() {
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
        checkMemoryBudget(plan_, options_.maxMemoryBytes, diags_);
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
    int patchVertices_ = 3;
    std::map<MeshDecl, int> meshIndex_;
    size_t draws_ = 0;
    // An open glBegin: the draw as the state stood at glBegin, and its vertices.
    struct Immediate {
        Step step;
        ImmediatePrimitive primitive = ImmediatePrimitive::Points;
        std::vector<double> points;
        bool valid = true;
    };
    std::optional<Immediate> imm_;
};

}  // namespace

bool MeshDecl::flat() const {
    switch (shape) {
    case CommandKind::QuadXY:
    case CommandKind::QuadXZ:
    case CommandKind::QuadYZ:
    case CommandKind::DiskXY: return true;
    case CommandKind::Triangles:
    case CommandKind::GlBegin: {
        // All points in one plane, within a small part of the points' extent.
        size_t n = points.size() / 3;
        auto p = [&](size_t i) { return glm::dvec3(points[3 * i], points[3 * i + 1], points[3 * i + 2]); };
        if (n < 4) return true;
        // Linear in the points (a search over pairs took seconds for 48k
        // points): the point farthest from the first gives a direction, the
        // one farthest from that line a plane; all must lie in it.
        glm::dvec3 lo = p(0), hi = p(0);
        for (size_t i = 1; i < n; ++i) {
            lo = glm::min(lo, p(i));
            hi = glm::max(hi, p(i));
        }
        const double eps = 1e-6 * std::max(glm::length(hi - lo), 1e-30);
        size_t a = 0;
        for (size_t i = 1; i < n; ++i)
            if (glm::length(p(i) - p(0)) > glm::length(p(a) - p(0))) a = i;
        const glm::dvec3 dir = p(a) - p(0);
        if (glm::length(dir) <= eps) return true;  // all at one point
        const glm::dvec3 unit = glm::normalize(dir);
        size_t b = 0;
        double far = 0;
        for (size_t i = 1; i < n; ++i) {
            double d = glm::length(glm::cross(p(i) - p(0), unit));
            if (d > far) far = d, b = i;
        }
        if (far <= eps) return true;  // all on one line
        const glm::dvec3 normal = glm::normalize(glm::cross(dir, p(b) - p(0)));
        for (size_t i = 1; i < n; ++i)
            if (std::abs(glm::dot(p(i) - p(0), normal)) > eps) return false;
        return true;
    }
    default: return false;
    }
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
    return Builder(script, options, diags).build();
}

}  // namespace glimmer
