// Every command word GLIB knows, with its spellings. Which of them the
// renderer supports is the plan's business, not the language's.
#pragma once
#include <optional>
#include <string_view>

namespace glimmer {

enum class CommandKind {
    Unknown,
    // window and view
    WindowSize, Ortho, Perspective, LookAt,
    // transforms
    Translate, Rotate, Scale, PushMatrix, PopMatrix,
    // state
    Background, Clear, Color, LineWidth, PointSize, Flat, Smooth, Timer, MessageBox, Gstap,
    Noise2D, Noise3D,
    // textures
    Texture2D, Texture3D, CubeMap, RenderToTexture,
    // shaders
    Vertex, Fragment, Geometry, TessControl, TessEvaluation, Program,
    // geometry
    QuadXY, QuadXZ, QuadYZ, Sphere, Torus, Box, Cylinder, Cone, DiskXY, Teapot, Obj, ObjAdj,
    WireBox, WireSphere, WireTorus, WireCylinder, WireCone, WireTeapot, WireObj,
    Triangles, LinesAdjacency, GlBegin, GlVertex, GlEnd, NumPatchVertices,
    PointCloud, JitterCloud, QuadBox,
};

// Case-insensitive lookup of a command word, aliases included
// (Persp, TransformBegin, RenderTargetTexture, ...). nullopt if unknown.
std::optional<CommandKind> lookupCommand(std::string_view word);

// The canonical spelling, e.g. "RenderToTexture".
std::string_view commandName(CommandKind kind);

}  // namespace glimmer
