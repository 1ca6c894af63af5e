// The CPU load step: every file a plan names, read and decoded, and every
// mesh built, before any OpenGL. The renderer only uploads what this holds,
// so `check` finds a missing image without a context, and a reader of
// untrusted files (image decoders, the OBJ loader) runs in one place.
//
// Contract:
//   - Only what `Usage` marks is loaded; everything else stays empty.
//   - Every failure is an error on the script line that named the file; the
//     rest still loads, so one run reports every problem.
//   - Shader texts are added to `sources`, so diagnostics can quote them.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "image/image.h"
#include "lang/diagnostics.h"
#include "plan/plan.h"
#include "plan/usage.h"

namespace glimmer {

// A texture file's contents: one of the three, by TextureDecl::Kind.
struct TextureFile {
    bool loaded = false;        // false: a render target, unused, or the file failed
    Image image;                // Texture2D from a file
    Volume volume;              // Texture3D from a .tex file
    std::array<Image, 6> faces; // CubeMap, +x -x +y -y +z -z
};

struct Assets {
    Usage used;
    std::vector<TextureFile> textures;                    // per Plan::textures
    std::vector<std::optional<Mesh>> meshes;              // per Plan::meshes; nullopt: unused or failed
    // Per Plan::programs, per stage: the shader's text; nullopt when it could
    // not be read (or the program is unused).
    std::vector<std::vector<std::optional<std::string>>> shaderTexts;
};

// Loads what the plan's needed passes use (all of it with `everything`).
// False when diags got errors.
bool loadAssets(const Plan& plan, bool everything, Diagnostics& diags, SourceTexts& sources, Assets& out);

// The vertex arrays of one shape command (reads the OBJ file for Obj,
// ObjAdj and WireObj). False with `error` when it cannot be built. With a
// `budget` (--max-memory), an OBJ that would take the `used` bytes past it
// is refused with the budget's message before it is parsed.
bool buildMesh(const MeshDecl& m, Mesh& mesh, std::string& error, std::uint64_t used = 0, std::uint64_t budget = 0);

}  // namespace glimmer
