// The watch's steps (pipeline/watch.h says what each does). Held by
// test_cli's CliWatch cases to exact summaries and refusals: a range whose
// bounds are not finite numbers is refused whole, never read as the range
// held before (issue 40: src/pipeline scored 2 of 3 in the first sampled
// mutants; docs/RELIABILITY.md).
#include "pipeline/watch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "plan/dependencies.h"
#include "shader/glsl_scan.h"
#include "util/numbers.h"

namespace glimmer {
namespace {

// Whether the user's FILE names this stage: as the script wrote it, as it
// was resolved, or by its tail ("bloom.frag" for "shaders/bloom.frag").
bool names(const std::string& file, const ShaderStage& stage) {
    auto endsWith = [](const std::string& s, const std::string& tail) {
        return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0 &&
               s[s.size() - tail.size() - 1] == '/';
    };
    return file == stage.shown || file == stage.path || endsWith(stage.path, file) || endsWith(stage.shown, file);
}

bool drawsWith(const Pass& pass, int program) {
    for (const auto& s : pass.steps)
        if (s.kind == Step::Kind::Draw && s.draw.program == program) return true;
    return false;
}

// The driver's words for an expression that does not compile at the
// watched line, said in the user's terms. Mesa: "`foo' undeclared", "no
// matching function for call to `glimmer_watch_store(mat3)'"; glslang (the
// page): "'foo' : undeclared identifier", "no matching overloaded function".
std::string explain(const std::string& driver, const WatchSpec& spec) {
    const std::string store(kWatchStore);
    if (size_t at = driver.find(store + "("); at != std::string::npos) {
        size_t end = driver.find(')', at);
        std::string type = end == std::string::npos ? "" : driver.substr(at + store.size() + 1, end - at - store.size() - 1);
        std::string what = type.empty() ? "its type" : "a " + type;
        if (type.rfind("mat", 0) == 0 || type.rfind("dmat", 0) == 0)
            return fmt::format("'{}' is {}: a matrix cannot be watched; watch a column ({}[0]) or an element ({}[0][0])",
                               spec.expression, what, spec.expression, spec.expression);
        return fmt::format("'{}' is {}, which cannot be watched: a watch shows a float, int, uint or bool, or a vector "
                           "of 2 to 4 of them (for a struct, watch one of its fields)", spec.expression, what);
    }
    if (driver.find("no matching overloaded function") != std::string::npos ||
        driver.find(store) != std::string::npos)
        return fmt::format("'{}' cannot be watched: a watch shows a float, int, uint or bool, or a vector of 2 to 4 of "
                           "them (not a matrix, a struct or an array; watch a column, field or element)", spec.expression);
    if (driver.find("undeclared") != std::string::npos) {
        std::string name;
        for (char q : {'`', '\''}) {
            size_t a = driver.find(q);
            size_t b = a == std::string::npos ? a : driver.find('\'', a + 1);
            if (b != std::string::npos && name.empty()) name = driver.substr(a + 1, b - a - 1);
        }
        if (name.empty()) name = spec.expression;
        return fmt::format("'{}' is not in scope at line {}: watch a variable declared before this line in the same "
                           "block or one around it, a uniform, or an input", name, spec.line);
    }
    return fmt::format("'{}' does not compile at line {}: {}", spec.expression, spec.line, driver);
}

}  // namespace

bool startWatch(const WatchSpec& spec, const Plan& plan, Renderer& renderer, Diagnostics& diags, Watch& out) {
    renderer.dropWatch();
    out = {};
    out.spec = spec;
    // The program: the one drawn last among those with a stage of that file.
    std::vector<std::string> shaders;
    for (int p = 0; p < int(plan.programs.size()); ++p) {
        const ProgramDecl& decl = plan.programs[size_t(p)];
        for (size_t k = 0; k < decl.stages.size(); ++k) {
            if (shaders.size() < 12) shaders.push_back(decl.stages[k].shown);
            if (!names(spec.file, decl.stages[k])) continue;
            for (int i = int(plan.passes.size()) - 1; i >= 0; --i)
                if (drawsWith(plan.passes[size_t(i)], p) && i > out.pass) {
                    out.pass = i, out.program = p, out.stage = k;
                    break;
                }
            if (out.program < 0) out.program = p, out.stage = k;
        }
    }
    if (out.program < 0) {
        diags.error(plan.scriptFile, {}, fmt::format("--watch: '{}' is not a shader of this script (its shaders: {})",
                                                     spec.file, fmt::join(shaders, ", ")));
        return false;
    }
    const ProgramDecl& decl = plan.programs[size_t(out.program)];
    const ShaderStage& stage = decl.stages[out.stage];
    out.path = stage.path;
    if (out.pass < 0) {
        diags.error(plan.scriptFile, decl.loc, fmt::format("--watch: Program {} draws nothing, so {} has no pixels to "
                                                           "watch", decl.name, stage.shown));
        return false;
    }
    out.vertex = stage.kind == ShaderStage::Kind::Vertex;
    if (stage.kind != ShaderStage::Kind::Fragment && !out.vertex) {
        diags.error(out.path, {spec.line, 1}, "a watch goes in a vertex or a fragment shader; this is another stage");
        return false;
    }
    std::vector<std::optional<std::string>> texts = renderer.programTexts(out.program);
    if (out.stage >= texts.size() || !texts[out.stage]) {
        diags.error(plan.scriptFile, decl.loc, fmt::format("--watch: Program {} was not built, so nothing can be "
                                                           "watched in it", decl.name));
        return false;
    }
    std::map<size_t, std::string> replaced;
    WatchedStage w = out.vertex ? watchVertex(*texts[out.stage], spec.line, spec.expression)
                                : watchFragment(*texts[out.stage], spec.line, spec.expression);
    if (!w.ok) {
        diags.error(out.path, {spec.line, w.column}, w.error);
        return false;
    }
    replaced[out.stage] = w.text;
    if (out.vertex) {
        size_t fragment = decl.stages.size();
        for (size_t k = 0; k < decl.stages.size(); ++k) {
            ShaderStage::Kind kind = decl.stages[k].kind;
            if (kind == ShaderStage::Kind::Fragment) fragment = k;
            if (kind != ShaderStage::Kind::Fragment && kind != ShaderStage::Kind::Vertex) {
                diags.error(out.path, {spec.line, w.column},
                            fmt::format("Program {} has a geometry or tessellation stage between its vertex and "
                                        "fragment shaders: a vertex watch needs the two to meet", decl.name));
                return false;
            }
        }
        WatchedStage f = fragment < texts.size() && texts[fragment] ? watchFragmentOfVertex(*texts[fragment]) : WatchedStage{};
        if (!f.ok) {
            diags.error(out.path, {spec.line, w.column}, f.error.empty() ? "the program has no fragment shader" : f.error);
            return false;
        }
        replaced[fragment] = f.text;
    }
    Diagnostics said;
    if (!renderer.prepareWatch(out.program, replaced, said)) {
        // Errors on the watched line are the expression's; elsewhere the
        // rewrite's own (a bug here), said as the driver said them.
        bool told = false;
        for (const Diagnostic& d : said.all()) {
            if (d.severity != Severity::Error || told) continue;
            if (d.file == out.path && d.loc.line == spec.line) {
                diags.error(out.path, {spec.line, w.column}, explain(d.message, spec));
                told = true;
            }
        }
        if (!told) {
            for (const Diagnostic& d : said.all()) diags.add(d);
            diags.error(out.path, {spec.line, w.column}, "the watch could not be built (the messages above are the "
                                                         "driver's on the rewritten shader)");
        }
        return false;
    }
    out.feeding = passesFeeding(plan, out.pass);
    return true;
}

WatchFrame drawWatch(Renderer& renderer, const Watch& watch, const UniformValues& values, double time,
                     const std::vector<bool>* feeding) {
    WatchFrame f;
    if (!renderer.renderWatch(watch.pass, values, time, feeding ? *feeding : watch.feeding)) return f;
    // Below and above the fixed range; the values' own has nothing outside it.
    const float most = std::numeric_limits<float>::max();
    std::optional<WatchSums> sums = watch.range ? renderer.sumWatch(float(watch.range->lo), float(watch.range->hi))
                                                : renderer.sumWatch(-most, most);
    if (!sums) return f;
    WatchStats& s = f.stats;
    s.width = sums->width, s.height = sums->height;
    s.components = std::clamp(sums->components, 0, 4);
    s.kind = sums->kind;
    for (size_t c = 0; c < 4; ++c) {  // none finite: as watchStats leaves it
        const bool any = sums->lo[c] <= sums->hi[c];
        s.lo[c] = any ? sums->lo[c] : std::numeric_limits<double>::infinity();
        s.hi[c] = any ? sums->hi[c] : -std::numeric_limits<double>::infinity();
    }
    s.drawn = sums->drawn, s.reached = sums->reached, s.nan = sums->nan, s.inf = sums->inf;
    s.below = sums->below, s.above = sums->above;
    s.fixed = watch.range.has_value();
    s.range = watchRangeOf(s, watch.range);
    std::array<std::array<unsigned char, 3>, 6> marks{};
    for (size_t m = 0; m < 6; ++m) marks[m] = {kWatchMarkers[m].r, kWatchMarkers[m].g, kWatchMarkers[m].b};
    renderer.colourWatch(float(s.range.lo), float(s.range.hi), watchScale(float(s.range.lo), float(s.range.hi)), marks);
    f.drawn = true;
    return f;
}

std::string watchValueAt(const Renderer& renderer, int x, int y) {
    WatchCapture one = renderer.readWatchCapture(x, y, 1, 1);
    if (one.value.empty()) return "outside the pass";
    return watchValueAt(one.value, one.info, 0, 0);
}

std::string watchTitle(const Watch& watch, const Plan& plan) {
    std::string program = watch.program >= 0 && size_t(watch.program) < plan.programs.size()
                              ? plan.programs[size_t(watch.program)].name
                              : "?";
    return fmt::format("{}:{} {}, pass {} (Program {})", watch.spec.file, watch.spec.line, watch.spec.expression,
                       watch.pass + 1, program);
}

bool parseWatchRange(const std::string& text, WatchRange& out, std::string& why) {
    size_t comma = text.find(',');
    auto number = [](std::string_view s, double& v) {
        while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
        while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
        auto [end, ec] = parseDouble(s.data(), s.data() + s.size(), v);  // libc++ of the page has no float from_chars
        return !s.empty() && ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
    };
    if (comma == std::string::npos || !number(std::string_view(text).substr(0, comma), out.lo) ||
        !number(std::string_view(text).substr(comma + 1), out.hi) || !(out.lo < out.hi)) {
        why = fmt::format("--watch-range '{}' is not LO,HI with LO less than HI (for example 0,1)", text);
        return false;
    }
    return true;
}

}  // namespace glimmer
