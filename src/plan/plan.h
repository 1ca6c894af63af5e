// The plan: a parsed script resolved into what the renderer needs. Files are
// found, uniforms typed by their written form, matrices computed, and the
// script cut into passes that say which target each writes and which
// textures it reads. Still no OpenGL: the plan can be built and tested
// without a context.
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "lang/diagnostics.h"
#include "lang/script.h"
#include "plan/limits.h"

namespace glimmer {

// One name-value pair of a Program line, as written. Its GL type is only
// known after the shader is linked; the renderer converts then.
struct UniformSetting {
    enum class Form {
        Range,     // <min current max>: a slider
        Bool,      // <true> <false> <0> <1>: a checkbox
        Color,     // {r g b [a]}: a colour button
        Array,     // [a b c ...]: a vector or array constant
        Constant,  // a bare number, most often a sampler's texture unit
    };
    std::string name;
    SourceLoc loc;
    Form form = Form::Constant;
    std::vector<double> values;  // Range: {current}; Bool: {0|1}; Color: rgba; Array/Constant: as written
    double min = 0, max = 0;     // Range only
};

struct ShaderStage {
    enum class Kind { Vertex, Fragment, Geometry, TessControl, TessEvaluation };
    Kind kind = Kind::Vertex;
    std::string path;  // resolved, openable
    std::string shown; // as the script wrote it, for messages
    SourceLoc loc;     // of the command that named it
};

struct ProgramDecl {
    std::string name;
    SourceLoc loc;
    std::vector<ShaderStage> stages;
    std::vector<UniformSetting> uniforms;
    bool gstap = false;  // GSTAP was given before this Program
    // What the script says about this pass, for the viewer: the MessageBox
    // texts since the previous Program, then the `##` comment block right
    // above the Program line (added by the driver, which has the text).
    std::string notes;
};

struct TextureDecl {
    // Texture2D, Texture3D, CubeMap: the OpenGL target the renderer binds it to.
    enum class Kind { Tex2D, Tex3D, Cube };
    enum class Source { File, Empty };
    Kind kind = Kind::Tex2D;
    Source source = Source::Empty;
    std::string path;   // resolved (File); a cube map's +x face
    std::string shown;  // as written (File); a cube map's +x face
    std::vector<std::string> facePaths, faceShown;  // Cube: six files, +x -x +y -y +z -z
    int width = 0, height = 0;  // Empty: as written; File: filled in when loaded
    int depth = 0;              // Tex3D Empty: as written
    // Glimmer extensions for render targets (docs/glib.md): the storage
    // format, and a mip chain made after each pass that writes it.
    enum class Format { RGBA8, RGBA16F, RGBA32F, R11F_G11F_B10F };
    Format format = Format::RGBA8;
    bool mips = false;
    // How lookups outside 0..1 read (Wrap, a Glimmer extension): GL_REPEAT,
    // GL_CLAMP_TO_EDGE or GL_MIRRORED_REPEAT. Cube maps always clamp.
    enum class Wrap { Repeat, Clamp, Mirror };
    Wrap wrap = Wrap::Repeat;
    SourceLoc loc;
    bool renderTarget = false;  // some pass writes it
    bool needsDepth = false;    // some pass writing it draws depth that matters
};

struct MeshDecl {
    CommandKind shape = CommandKind::QuadXY;
    // The command's numbers, defaults filled in. GlBegin: {primitive}, an
    // ImmediatePrimitive (geometry/mesh.h) as a number.
    std::vector<double> params;
    std::vector<double> points;  // Triangles, LinesAdjacency, GlBegin: x y z per point
    std::string path;            // Obj, ObjAdj, WireObj
    SourceLoc loc;
    bool operator<(const MeshDecl& o) const {
        return std::tie(shape, params, points, path) < std::tie(o.shape, o.params, o.points, o.path);
    }
    // True when nothing drawn with it can hide another part of it (a quad, a
    // disk, triangles in one plane): one such draw needs no depth buffer.
    bool flat() const;
};

struct Draw {
    int mesh = -1;
    int program = -1;  // -1: fixed function
    glm::mat4 projection{1.f};
    glm::mat4 modelView{1.f};
    glm::mat4 view{1.f};  // the LookAt part of modelView, so a viewer can turn the scene about the eye's target
    glm::vec4 color{1.f};
    std::map<int, int> units;  // texture unit -> texture, as bound when the draw was written (the last one)
    // Textures of other kinds still bound on a unit of `units`: OpenGL keeps
    // one binding per target (2-D, 3-D, cube map) on each unit, so a CubeMap
    // and a Texture2D on unit 6 are both there for their own samplers.
    std::map<int, std::vector<int>> otherTargets;
    // Every texture bound on `unit` (the last one first), whatever its kind.
    std::vector<int> texturesOn(int unit) const;
    // The texture of `kind` bound on `unit`, or -1.
    int textureOn(int unit, TextureDecl::Kind kind, const std::vector<TextureDecl>& textures) const;
    float lineWidth = 1.f, pointSize = 1.f;
    bool flatShading = false;
    int patchVertices = 3;  // NumPatchVertices: GL_PATCH_VERTICES for patch meshes (OpenGL's default 3)
    SourceLoc loc;
};

struct Step {
    enum class Kind { Clear, Draw };
    Kind kind = Kind::Clear;
    glm::vec4 clearColor{0.f};
    Draw draw;
    // A Clear: the later step of the same pass whose draw covers the whole
    // target, so the Clear cannot show if that draw paints every pixel it
    // covers (plan/hidden_clears.h); -1: none.
    int hiddenBy = -1;
};

// Everything drawn between two target changes.
struct Pass {
    std::vector<int> targets;  // textures written (colour attachments in order); empty: the screen
    SourceLoc loc;             // where the target was chosen (or the first step)
    std::vector<Step> steps;
    std::set<int> reads;       // textures its draws may sample
    bool needsDepth = false;
    bool needed = true;        // false: nothing downstream reads what it writes
};

struct Plan {
    std::string scriptFile;
    int width = 600, height = 600;  // the screen: --size, else WindowSize, else glman's 600x600
    double timerPeriod = 10.0;
    // The built-in noise textures' sizes (Noise2D, Noise3D; glman's 64). The
    // renderer makes them only for programs that declare Noise2 / Noise3.
    int noise2DRes = 64, noise3DRes = 64;
    SourceLoc noise2DLoc, noise3DLoc;  // the Noise2D / Noise3D line that set them (line 0: glman's default)
    std::uint64_t scriptBytes = 0;     // what parsing the script took (lang/lexer.h): in --max-memory too
    std::vector<ProgramDecl> programs;
    std::vector<TextureDecl> textures;
    std::vector<MeshDecl> meshes;
    std::vector<Pass> passes;
    std::map<int, int> finalUnits;  // texture unit -> texture bound there when the script ends
    std::uint64_t maxMemoryBytes = 0;  // --max-memory: the load step counts image files against it too

    bool screenNeeded() const;
};

struct PlanOptions {
    int width = 0, height = 0;             // 0: from the script
    std::vector<std::string> includeDirs;  // -I
    std::set<int> keepTargets;             // texture units the user wants to see (--dump): never dropped
    // --stand-ins: a missing image, cube-map face, 3-D .tex or OBJ is a warning
    // and its path stays empty; the load step makes a stand-in (assets/stand_ins.h).
    bool standIns = false;
    std::uint64_t maxMemoryBytes = kDefaultMaxMemoryMiB << 20;  // textures and targets together (--max-memory)
    bool sandbox = false;                  // --sandbox: files only inside the script's folder and -I folders (plan/sandbox.h)
};

// Resolves and checks a parsed script. Problems go to `diags`; the plan is
// usable (renders what it can) unless diags has errors.
Plan buildPlan(const Script& script, const PlanOptions& options, Diagnostics& diags);

// "RGBA16F" -> Format (case-insensitive); false for anything else.
bool parseTextureFormat(const std::string& word, TextureDecl::Format& out);
const char* textureFormatName(TextureDecl::Format f);
// "clamp" -> Wrap::Clamp (case-insensitive; also OpenGL's names, with or
// without GL_: CLAMP_TO_EDGE, MIRRORED_REPEAT); false for anything else.
bool parseTextureWrap(const std::string& word, TextureDecl::Wrap& out);
const char* textureWrapName(TextureDecl::Wrap w);
bool isFloatFormat(TextureDecl::Format f);

// A size written relative to the output: "w", "h", "w/2", "h*2" (integer
// divide, at least 1). False if `word` is not of that form.
bool relativeSize(const std::string& word, int width, int height, int& out);

// Finds `name` as glman would: absolute, else the script's folder, else the
// project folders ../shaders and ../textures beside it, else each -I folder.
// Empty when not found; `tried` lists where it looked.
std::string resolveFile(const std::string& scriptFile, const std::string& name,
                        const std::vector<std::string>& includeDirs, std::vector<std::string>* tried);

// A file in one of `folders` whose name is `name` but for letter case
// ('bright.frag' for 'Bright.frag', written where names ignore case), as
// `name` would give it; "" when none. Reads at most 2000 names a folder.
std::string sameNameButCase(const std::vector<std::string>& folders, const std::string& name);

}  // namespace glimmer
