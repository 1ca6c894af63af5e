// Stand-ins for files a script names but the repository lacks (--stand-ins):
// course repositories often leave out large models and cube-map images. The
// plan warns where the script names the file and leaves its path empty; the
// load step then makes one of these instead of reading it. A missing shader
// has no stand-in: nothing sensible can replace code.
#pragma once
#include <string>

#include "assets/assets.h"

namespace glimmer {

// The size of a stand-in picture when nothing tells a better one.
constexpr int kStandInSize = 256;
// Its checks: 8 x 8 squares, magenta and grey, the name written across.
Image standInImage(const std::string& name, int size = kStandInSize);

// A texture whose file (or, for a cube map, some face) is missing: a
// labelled checkerboard (faces the size of the faces present), or for a 3-D
// texture the built-in 4-octave noise (64^3). False with `why` when a face
// that is present fails to load.
bool standInTexture(const TextureDecl& t, TextureFile& out, std::string& why);
bool needsStandIn(const TextureDecl& t);

// A missing Obj, ObjAdj or WireObj file: a sphere of the radius the plan
// chose for the view (MeshDecl::params[0]; 1 when none), with adjacency or as
// its edges as the command asks.
bool needsStandIn(const MeshDecl& m);
Mesh standInMesh(const MeshDecl& m);

}  // namespace glimmer
