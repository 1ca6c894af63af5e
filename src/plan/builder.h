// The plan builder's state machine, shared by the files that implement it
// (plan_builder.cpp: the walk, matrices and passes; plan_textures.cpp;
// plan_shapes.cpp; plan_programs.cpp). Private to src/plan: the public
// contract is plan.h.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/mesh.h"
#include "geometry/shape_registry.h"
#include "plan/plan.h"

namespace glimmer {
namespace plan_detail {


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

    Plan build();

private:
    const std::string& file() const { return script_.file; }

    // Checks that a command has between lo and hi arguments, all numbers.
    bool numbers(const Command& c, size_t lo, size_t hi);
    // The same with the count from the command's row (lang/commands.cpp).
    bool numbers(const Command& c);

    double num(const Command& c, size_t i, double fallback) const;
    // Argument i, else the default in the command's row.
    double num(const Command& c, size_t i) const;

    Pass& pass() { return plan_.passes.back(); }
    // The aspect ratio the projection keeps. Only the screen is widened, as
    // glman's window reshape does; a quad drawn to cover a texture target
    // must cover it exactly, whatever the texture's shape.
    std::pair<int, int> aspectSize() const;

    void command(const Command& c);

    // A shape made from numbers (geometry/shape_registry.h): checked, completed, drawn.
    void numberShape(const Command& c, const ShapeRule& rule);
    void torusOrderCheck(const Command& c, const std::vector<double>& numbers);

    void noiseRes(const Command& c);

    // One point from an `[x y z]` group (a 2-number group lies at z = 0).
    std::optional<glm::dvec3> point(const Command& c, const Arg& a);

    // Triangles (3 points a primitive), LinesAdjacency (4).
    void pointsMesh(const Command& c, size_t per);

    void glBegin(const Command& c);

    void glVertex(const Command& c);

    // `end` is null when the block is closed by a new glBegin or the end of the script.
    void glEnd(const Command* end);

    std::optional<glm::vec4> colorArgs(const Command& c);

    void ortho(const Command& c);

    void lookAt(const Command& c);

    int unitArg(const Command& c, const Arg& a);

    // Finds a texture file; false (reported) when it is not there.
    // Resolves a file the script names, as glman would or, under --sandbox,
    // only inside the sandbox. `usable`: found, or a stand-in takes its place
    // (--stand-ins); false when the command cannot go on (reported).
    // `standIn` says, for --stand-ins, what takes a missing file's place.
    std::string findFile(const Arg& a, const char* what, bool& usable,
                         const std::string& standIn = "a stand-in takes its place");
    // Counts a draw; false (reported once) past kMaxDraws.
    bool countDraw(SourceLoc loc);
    bool textureFile(const Arg& a, std::string& path);

    // Binds `t` to `unit` where the command stands. Scripts re-bind the same
    // file many times (one skybox face per quad): one texture per file (per
    // six files for a cube map) is shared.
    void bindTexture(int unit, TextureDecl t);

    // Checks `w h [d]` of an empty texture.
    bool sizeArgs(const Command& c, size_t first, size_t n);

    bool allNumbers(const Command& c, size_t first);

    // What Texture2D and Texture3D share: the unit, and the file form
    // (`unit file`). Returns the unit, or -1 after an error; `isFile` says
    // whether the file form was read into `t`.
    int textureHead(const Command& c, TextureDecl::Kind kind, const char* usage, TextureDecl& t, bool& isFile);

    void texture2D(const Command& c);

    // A render target's width or height: a whole number, or relative to
    // the output ("w/2") so a chain of targets follows the window.
    bool targetSize(const Arg& a, int& out);

    void texture3D(const Command& c);

    void cubeMap(const Command& c);

    // The file under another case of the same name in a folder looked in,
    // resolved as the name itself would be, with a warning naming both; ""
    // when there is none (glman ran on Windows: 'Bright.frag' opened
    // bright.frag there).
    std::string caseVariant(const Arg& a, const char* what, const std::vector<std::string>& tried);
    bool notFound(SourceLoc loc, const char* what, const std::string& name, const std::vector<std::string>& tried,
                  const std::string& standIn);

    void renderToTexture(const Command& c);

    // Wrap MODE: the wrap of the textures declared after it.
    void wrap(const Command& c);

    void stage(const Command& c, ShaderStage::Kind kind);

    void program(const Command& c);

    void obj(const Command& c);

    int meshIndex(const MeshDecl& m);

    // A draw with the state in force now; its mesh is filled in by the caller.
    Step drawStep(SourceLoc loc);

    void mesh(const Command& c, std::vector<double> params, const std::string& path = {}, std::vector<double> points = {});

    // Which textures a draw may sample: the units its Program's integer
    // constants name (how samplers get their units), and unit 0, where an
    // unset sampler looks.
    std::set<int> drawReads(const Draw& d) const;

    void finish();

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
    std::map<int, int> units_;  // unit -> the texture bound there last
    // unit -> the texture bound there for each kind (OpenGL's one binding per target)
    std::map<int, std::map<TextureDecl::Kind, int>> unitTargets_;
    TextureDecl::Wrap wrap_ = TextureDecl::Wrap::Repeat;  // Wrap in force for new textures
    std::map<ShaderStage::Kind, ShaderStage> stages_;
    std::set<ShaderStage::Kind> missingStages_;  // named, but the file was not found
    int program_ = -1;
    int patchVertices_ = 3;
    std::map<MeshDecl, int> meshIndex_;
    // An open glBegin: the draw as the state stood at glBegin, and its vertices.
    struct Immediate {
        Step step;
        ImmediatePrimitive primitive = ImmediatePrimitive::Points;
        std::vector<double> points;
        bool valid = true;
    };
    std::optional<Immediate> imm_;
    size_t draws_ = 0;
    std::string pendingNotes_;  // MessageBox texts waiting for the next Program
};

}  // namespace plan_detail
}  // namespace glimmer
