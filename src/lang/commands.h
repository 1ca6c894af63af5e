// Every command word GLIB knows: one row each (commands.cpp, kRules) with
// its spelling, its arguments and, for commands of numbers only, their count
// and defaults. What a command does is the plan's business, not the language's.
#pragma once
#include <array>
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
    Texture2D, Texture3D, CubeMap, RenderToTexture, Wrap,
    // shaders
    Vertex, Fragment, Geometry, TessControl, TessEvaluation, Program,
    // geometry
    QuadXY, QuadXZ, QuadYZ, Sphere, Torus, Box, Cylinder, Cone, DiskXY, Teapot, Obj, ObjAdj,
    WireBox, WireSphere, WireTorus, WireCylinder, WireCone, WireTeapot, WireObj,
    Triangles, LinesAdjacency, GlBegin, GlVertex, GlEnd, NumPatchVertices,
    PointCloud, JitterCloud, QuadBox,
};

// A command's row: spelling, arguments, and for commands of numbers only,
// how many they take and the defaults of the ones left out.
struct CommandRule {
    CommandKind kind;
    std::string_view name;  // canonical spelling, e.g. "RenderToTexture"
    std::string_view args;  // as docs/glib.md writes them, e.g. "x y [z]"
    int minNumbers = -1, maxNumbers = -1;  // -1: the arguments are not all numbers
    std::array<double, 9> defaults{};      // for numbers left out (LookAt has nine)
};

// The row of a command; null for Unknown.
const CommandRule* commandRule(CommandKind kind);
// Every row, in the order of the table.
const CommandRule* commandRulesBegin();
const CommandRule* commandRulesEnd();

// Case-insensitive lookup of a command word, aliases included
// (Persp, TransformBegin, RenderTargetTexture, ...). nullopt if unknown.
std::optional<CommandKind> lookupCommand(std::string_view word);

// The canonical spelling, e.g. "RenderToTexture".
std::string_view commandName(CommandKind kind);

}  // namespace glimmer
