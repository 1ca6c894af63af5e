// Cube maps and 3-D texture files from disk. No OpenGL here.
#pragma once
#include <array>
#include <string>

#include "image/image.h"

namespace glimmer {

// The face names in glman's (and OpenGL's) order: +x -x +y -y +z -z, the
// order of GL_TEXTURE_CUBE_MAP_POSITIVE_X + i.
inline constexpr std::array<const char*, 6> kCubeFaceNames = {"+x", "-x", "+y", "-y", "+z", "-z"};

// Loads the six faces of `CubeMap unit +x -x +y -y +z -z` with loadImage.
// Every face must be square and the same size as the first (+x). On failure
// returns false, leaves `faces` untouched and sets `error` to one line naming
// the face and its file, e.g. "cube map face -y (sky_dn.bmp) is 64x32; faces
// must be square" or "cube map face +z (b.bmp) is 32x32, but face +x is
// 64x64; all faces must be the same size". Faces keep the type they loaded
// with (a .hdr face is F32 beside U8 faces).
//
// Rows stay in Image order (row 0 the top of the picture). Note for the
// uploader: OpenGL's cube map faces put t = 0 at the TOP of each face as seen
// from inside the cube (the RenderMan convention), so faces go to
// glTexImage2D in this order, NOT flipped as 2-D textures are.
bool loadCubeMap(const std::array<std::string, 6>& paths, std::array<Image, 6>& faces, std::string& error);

// Reads glman's raw 3-D .tex file (see decodeTex3D). On failure returns false
// and sets `error`: "cannot open PATH", or "PATH: " + decodeTex3D's reason.
bool loadVolume(const std::string& path, Volume& out, std::string& error);

}  // namespace glimmer
