// Texture2D, Texture3D, CubeMap, Noise2D/3D and RenderToTexture: texture
// declarations, their files, units and render targets.
// Held by test_plan's PlanTest.TextureArgumentErrors to every refusal's exact
// message, a negative unit among them (issue 40: src/plan scored 2 of 5 in
// the first sampled mutants; docs/RELIABILITY.md).
#include "plan/builder.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "plan/limits.h"
#include "plan/sandbox.h"
#include "plan/uniform_forms.h"

namespace glimmer {
namespace plan_detail {

void Builder::noiseRes(const Command& c) {
    bool two = c.kind == CommandKind::Noise2D;
    if (!numbers(c)) return;
    double res = num(c, 0);
    double hi = two ? 4096 : 512;
    if (res != std::floor(res) || res < 1 || res > hi) {
        diags_.error(file(), c.loc, fmt::format("{}'s resolution must be a whole number from 1 to {}", c.spelled, hi));
        return;
    }
    (two ? plan_.noise2DRes : plan_.noise3DRes) = int(res);
    (two ? plan_.noise2DLoc : plan_.noise3DLoc) = c.loc;
}

int Builder::unitArg(const Command& c, const Arg& a) {
    if (a.kind != Arg::Kind::Number || a.number != std::floor(a.number) || a.number < 0 || a.number > 31) {
        diags_.error(file(), a.loc, fmt::format("{} needs a texture unit from 0 to 31, not '{}'", c.spelled, a.text));
        return -1;
    }
    return int(a.number);
}

// Finds a texture file; false (reported) when it is not there.
bool Builder::textureFile(const Arg& a, std::string& path) {
    bool usable = false;
    path = findFile(a, "texture", usable);
    return usable;
}

std::string Builder::findFile(const Arg& a, const char* what, bool& usable, const std::string& standIn) {
    std::vector<std::string> tried;
    usable = false;
    if (!options_.sandbox) {
        std::string path = resolveFile(file(), a.text, options_.includeDirs, &tried);
        if (path.empty()) path = caseVariant(a, what, tried);
        usable = !path.empty() || notFound(a.loc, what, a.text, tried, standIn);
        return path;
    }
    std::string path, why;
    switch (resolveSandboxed(file(), a.text, options_.includeDirs, path, tried, why)) {
    case SandboxLookup::Found: usable = true; return path;
    case SandboxLookup::NotFound:
        path = caseVariant(a, what, tried);
        usable = !path.empty() || notFound(a.loc, what, a.text, tried, standIn);
        return path;
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
void Builder::bindTexture(int unit, TextureDecl t) {
    if (t.kind != TextureDecl::Kind::Cube) t.wrap = wrap_;
    if (t.source == TextureDecl::Source::File) {
        for (size_t i = 0; i < plan_.textures.size(); ++i) {
            const TextureDecl& o = plan_.textures[i];
            if (o.source == TextureDecl::Source::File && o.kind == t.kind && o.path == t.path &&
                o.facePaths == t.facePaths && o.wrap == t.wrap && (!options_.standIns || o.faceShown == t.faceShown)) {
                units_[unit] = int(i);
                unitTargets_[unit][t.kind] = int(i);
                return;
            }
        }
    }
    unitTargets_[unit][t.kind] = int(plan_.textures.size());
    plan_.textures.push_back(std::move(t));
    units_[unit] = int(plan_.textures.size()) - 1;
}

// Checks `w h [d]` of an empty texture.
bool Builder::sizeArgs(const Command& c, size_t first, size_t n) {
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

bool Builder::allNumbers(const Command& c, size_t first) {
    for (size_t i = first; i < c.args.size(); ++i)
        if (c.args[i].kind != Arg::Kind::Number) return false;
    return true;
}

// What Texture2D and Texture3D share: the unit, and the file form
// (`unit file`). Returns the unit, or -1 after an error; `isFile` says
// whether the file form was read into `t`.
int Builder::textureHead(const Command& c, TextureDecl::Kind kind, const char* usage, TextureDecl& t, bool& isFile) {
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

void Builder::texture2D(const Command& c) {
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
bool Builder::targetSize(const Arg& a, int& out) {
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

void Builder::texture3D(const Command& c) {
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

void Builder::cubeMap(const Command& c) {
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

std::string Builder::caseVariant(const Arg& a, const char* what, const std::vector<std::string>& tried) {
    const std::string other = sameNameButCase(tried, a.text);
    if (other.empty()) return {};
    std::vector<std::string> again;
    std::string path, why;
    if (!options_.sandbox) path = resolveFile(file(), other, options_.includeDirs, &again);
    else if (resolveSandboxed(file(), other, options_.includeDirs, path, again, why) != SandboxLookup::Found) path.clear();
    if (path.empty()) return {};
    diags_.warning(file(), a.loc, fmt::format("{} '{}' is '{}' on disk: opened it, as Windows and macOS do; write it "
                                              "'{}' for Linux", what, a.text, other, other));
    return path;
}

// An error; with --stand-ins (not for a shader) a warning, and true: the
// path stays empty and the load step makes a stand-in (assets/stand_ins.h).
bool Builder::notFound(SourceLoc loc, const char* what, const std::string& name, const std::vector<std::string>& tried,
                       const std::string& standIn) {
    std::string where;
    for (const auto& d : tried) where += (where.empty() ? "" : ", ") + d;
    std::string message = fmt::format("cannot find {} '{}' (looked in {})", what, name, where);
    // Written on Windows or macOS, where 'Bright.frag' opens bright.frag.
    if (std::string other = sameNameButCase(tried, name); !other.empty())
        message += fmt::format("; did you mean '{}'?", other);
    bool useStandIn = options_.standIns && std::string_view(what) != "shader";
    if (useStandIn) diags_.warning(file(), loc, message + "; " + standIn + " (--stand-ins)");
    else diags_.error(file(), loc, message);
    return useStandIn;
}

void Builder::renderToTexture(const Command& c) {
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
        // The unit's 2-D texture, also when a cube map or volume was bound
        // there after it (they sit on other targets of the unit).
        auto it = units_.find(unit);
        if (it == units_.end()) {
            diags_.error(file(), a.loc, fmt::format("no texture on unit {} to render into; "
                                                    "give it one first with Texture2D {} width height", unit, unit));
            return;
        }
        int index = it->second;
        const auto& kinds = unitTargets_[unit];
        if (auto flat = kinds.find(TextureDecl::Kind::Tex2D); flat != kinds.end()) index = flat->second;
        const TextureDecl& t = plan_.textures[size_t(index)];
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
        p.targets.push_back(index);
    }
    plan_.passes.push_back(std::move(p));
}

void Builder::wrap(const Command& c) {
    TextureDecl::Wrap w{};
    if (c.args.size() != 1 || c.args[0].kind != Arg::Kind::Word || !parseTextureWrap(c.args[0].text, w)) {
        diags_.error(file(), c.args.size() == 1 ? c.args[0].loc : c.loc,
                     fmt::format("Wrap takes one of repeat, clamp or mirror{}",
                                 c.args.size() == 1 ? fmt::format(", not '{}'", c.args[0].text) : std::string()));
        return;
    }
    wrap_ = w;
}

}  // namespace plan_detail

}  // namespace glimmer
