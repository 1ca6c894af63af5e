// The shape commands: one mesh declaration per distinct shape, drawn with
// the state in force where the command stands.
#include "plan/builder.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "plan/limits.h"
#include "plan/stand_in_size.h"
#include "plan/uniform_forms.h"

namespace glimmer {
namespace plan_detail {


// A command of a shape made from numbers: checked and completed by its row.
void Builder::numberShape(const Command& c, const ShapeRule& rule) {
    if (!numbers(c, rule.minArgs, rule.maxArgs)) return;
    const ShapeRule::Count& k = rule.count;
    if (k.arg >= 0 && size_t(k.arg) < c.args.size()) {
        double v = c.args[size_t(k.arg)].number;
        if (!wholeIn(v, k.lo, k.hi)) {
            diags_.error(file(), c.args[size_t(k.arg)].loc,
                         fmt::format("{}'s {} must be a whole number from {} to {}", c.spelled, k.what, k.lo, k.hi));
            return;
        }
    }
    if (rule.countsFrom >= 0)
        for (size_t i = size_t(rule.countsFrom); i < c.args.size(); ++i)
            if (!wholeIn(c.args[i].number, rule.countsLo, kMaxSubdivisions)) {
                diags_.error(file(), c.args[i].loc, fmt::format("{}'s counts must be whole numbers from {} to {}; not '{}'",
                                                                c.spelled, rule.countsLo, kMaxSubdivisions, c.args[i].text));
                return;
            }
    std::vector<double> written;
    for (const auto& a : c.args) written.push_back(a.number);
    std::vector<double> numbers = completeShapeNumbers(rule, written);
    if (rule.name == "Torus" || rule.name == "WireTorus") torusOrderCheck(c, numbers);
    mesh(c, std::move(numbers));
}

// glman (like glutSolidTorus) reads the tube's radius first and the ring's
// second; glman's manual names them the other way round on its Torus line,
// so scripts exist in both orders. A tube wider than its ring is drawn as
// written (a lump with no hole), but the student is told how it was read.
void Builder::torusOrderCheck(const Command& c, const std::vector<double>& numbers) {
    if (c.args.empty() || numbers[0] <= numbers[1]) return;
    const std::string tube = c.args[0].text;
    const std::string ring = c.args.size() > 1 ? c.args[1].text : fmt::format("{}", numbers[1]);
    diags_.warning(file(), c.args[0].loc,
                   fmt::format("{} read in glman's order (tube radius, then ring radius): a tube of radius {} around a "
                               "ring of radius {}, which has no hole; for a ring write '{} {} {}'",
                               c.spelled, tube, ring, c.spelled, ring, tube));
}

// One point from an `[x y z]` group (a 2-number group lies at z = 0).
std::optional<glm::dvec3> Builder::point(const Command& c, const Arg& a) {
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
void Builder::pointsMesh(const Command& c, size_t per) {
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

void Builder::glBegin(const Command& c) {
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

void Builder::glVertex(const Command& c) {
    if (!imm_) {
        diags_.warning(file(), c.loc, "glVertex outside glBegin ... glEnd; ignored");
        return;
    }
    if (!numbers(c)) return;
    double w = num(c, 3);
    if (w == 0) {
        diags_.error(file(), c.args[3].loc, "glVertex with w = 0 is a point at infinity; ignored");
        return;
    }
    imm_->points.insert(imm_->points.end(), {num(c, 0) / w, num(c, 1) / w, num(c, 2) / w});
}

// `end` is null when the block is closed by a new glBegin or the end of the script.
void Builder::glEnd(const Command* end) {
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

void Builder::obj(const Command& c) {
    if (c.args.size() != 1 || c.args[0].kind != Arg::Kind::Word) {
        diags_.error(file(), c.loc, fmt::format("{} takes one .obj file name", c.spelled));
        return;
    }
    // A missing model's stand-in (--stand-ins) is a sphere sized to the space
    // the script gives its object (plan/stand_in_size.h), so it is seen.
    auto [w, h] = aspectSize();
    const float radius = standInRadius(projection_.matrix(w, h), view_ * model_);
    const char* shape = c.kind == CommandKind::WireObj ? "wire sphere" : "sphere";
    bool usable = false;
    std::string path = findFile(c.args[0], "model", usable,
                                fmt::format("a {} of radius {:.3g} stands in for it, {:.0f}% of the view's height",
                                            shape, radius, 100 * kStandInViewShare));
    if (!usable) return;
    mesh(c, path.empty() ? std::vector<double>{double(radius)} : std::vector<double>{}, path);
}

int Builder::meshIndex(const MeshDecl& m) {
    auto [it, added] = meshIndex_.try_emplace(m, int(plan_.meshes.size()));
    if (added) plan_.meshes.push_back(m);
    return it->second;
}

// Counts a draw; false (reported once) past kMaxDraws.
bool Builder::countDraw(SourceLoc loc) {
    if (++draws_ <= kMaxDraws) return true;
    if (draws_ == kMaxDraws + 1)
        diags_.error(file(), loc, fmt::format("more than {} draws; this one and those after it are not drawn", kMaxDraws));
    return false;
}

void Builder::mesh(const Command& c, std::vector<double> params, const std::string& path, std::vector<double> points) {
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

}  // namespace plan_detail

}  // namespace glimmer
