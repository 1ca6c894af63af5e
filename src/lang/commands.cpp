#include "lang/commands.h"

#include <array>
#include <iterator>
#include <cctype>
#include <utility>

namespace glimmer {

namespace {

// One row per command, in the spirit of clox's rules[]: its canonical
// spelling, its arguments as docs/glib.md writes them, and for commands that
// take only numbers how many and glman's defaults for those left out. The
// shapes' numbers live in geometry/shape_registry.cpp (the plan reads both).
constexpr CommandRule kRules[] = {
    {CommandKind::WindowSize, "WindowSize", "width height", 2, 2, {}},
    {CommandKind::Ortho, "Ortho", "[left right bottom top]", 4, 4, {}},
    {CommandKind::Perspective, "Perspective", "[fovy]", 0, 1, {50}},
    {CommandKind::LookAt, "LookAt", "eyex eyey eyez  atx aty atz  upx upy upz", 9, 9, {0, 0, 0, 0, 0, 0, 0, 1, 0}},
    {CommandKind::Translate, "Translate", "x y [z]", 2, 3, {0, 0, 0}},
    {CommandKind::Rotate, "Rotate", "degrees ax ay az", 4, 4, {0, 0, 0, 0}},
    {CommandKind::Scale, "Scale", "s | sx sy sz", 1, 3, {1, 1, 1}},
    {CommandKind::PushMatrix, "PushMatrix", "", 0, 0, {}},
    {CommandKind::PopMatrix, "PopMatrix", "", 0, 0, {}},
    {CommandKind::Background, "Background", "r g b [a] | {r g b [a]}", -1, -1, {}},
    {CommandKind::Clear, "Clear", "", 0, 0, {}},
    {CommandKind::Color, "Color", "r g b [a] | {r g b [a]}", -1, -1, {}},
    {CommandKind::LineWidth, "LineWidth", "width", 1, 1, {1}},
    {CommandKind::PointSize, "PointSize", "size", 1, 1, {1}},
    {CommandKind::Flat, "Flat", "", 0, 0, {}},
    {CommandKind::Smooth, "Smooth", "", 0, 0, {}},
    {CommandKind::Timer, "Timer", "[seconds]", 0, 1, {10}},
    {CommandKind::MessageBox, "MessageBox", "text", -1, -1, {}},
    {CommandKind::Gstap, "GSTAP", "", 0, 0, {}},
    {CommandKind::Noise2D, "Noise2D", "[resolution]", 0, 1, {64}},
    {CommandKind::Noise3D, "Noise3D", "[resolution]", 0, 1, {64}},
    {CommandKind::Texture2D, "Texture2D", "unit file | unit width height [format [mips]]", -1, -1, {}},
    {CommandKind::Texture3D, "Texture3D", "unit file | unit width height depth", -1, -1, {}},
    {CommandKind::CubeMap, "CubeMap", "unit +x -x +y -y +z -z", -1, -1, {}},
    {CommandKind::RenderToTexture, "RenderToTexture", "[unit ...]", -1, -1, {}},
    {CommandKind::Wrap, "Wrap", "repeat | clamp | mirror", -1, -1, {}},
    {CommandKind::Vertex, "Vertex", "file", -1, -1, {}},
    {CommandKind::Fragment, "Fragment", "file", -1, -1, {}},
    {CommandKind::Geometry, "Geometry", "file", -1, -1, {}},
    {CommandKind::TessControl, "TessControl", "file", -1, -1, {}},
    {CommandKind::TessEvaluation, "TessEvaluation", "file", -1, -1, {}},
    {CommandKind::Program, "Program", "name [uniform value ...]", -1, -1, {}},
    {CommandKind::QuadXY, "QuadXY", "z size [nx ny]", -1, -1, {}},
    {CommandKind::QuadXZ, "QuadXZ", "y size [nx nz]", -1, -1, {}},
    {CommandKind::QuadYZ, "QuadYZ", "x size [ny nz]", -1, -1, {}},
    {CommandKind::Sphere, "Sphere", "[radius [slices [stacks]]]", -1, -1, {}},
    {CommandKind::Torus, "Torus", "[tube [ring [sides [rings]]]]", -1, -1, {}},
    {CommandKind::Box, "Box", "[dx [dy dz]]", -1, -1, {}},
    {CommandKind::Cylinder, "Cylinder", "[radius [height [slices]]]", -1, -1, {}},
    {CommandKind::Cone, "Cone", "[radius [height [slices]]]", -1, -1, {}},
    {CommandKind::DiskXY, "DiskXY", "[radius [slices]]", -1, -1, {}},
    {CommandKind::Teapot, "Teapot", "[size [subdivisions]]", -1, -1, {}},
    {CommandKind::Obj, "Obj", "file", -1, -1, {}},
    {CommandKind::ObjAdj, "ObjAdj", "file", -1, -1, {}},
    {CommandKind::WireBox, "WireBox", "[dx [dy dz]]", -1, -1, {}},
    {CommandKind::WireSphere, "WireSphere", "[radius [slices [stacks]]]", -1, -1, {}},
    {CommandKind::WireTorus, "WireTorus", "[tube [ring [sides [rings]]]]", -1, -1, {}},
    {CommandKind::WireCylinder, "WireCylinder", "[radius [height [slices]]]", -1, -1, {}},
    {CommandKind::WireCone, "WireCone", "[radius [height [slices]]]", -1, -1, {}},
    {CommandKind::WireTeapot, "WireTeapot", "[size [subdivisions]]", -1, -1, {}},
    {CommandKind::WireObj, "WireObj", "file", -1, -1, {}},
    {CommandKind::Triangles, "Triangles", "[x y z] [x y z] [x y z] ...", -1, -1, {}},
    {CommandKind::LinesAdjacency, "LinesAdjacency", "[x y z] x4 ...", -1, -1, {}},
    {CommandKind::GlBegin, "glBegin", "primitive", -1, -1, {}},
    {CommandKind::GlVertex, "glVertex", "x y [z [w]]", 2, 4, {0, 0, 0, 1}},
    {CommandKind::GlEnd, "glEnd", "", 0, 0, {}},
    {CommandKind::NumPatchVertices, "NumPatchVertices", "count", 1, 1, {}},
    {CommandKind::PointCloud, "PointCloud", "[count [size]]", -1, -1, {}},
    {CommandKind::JitterCloud, "JitterCloud", "[n [size [jitter]]]", -1, -1, {}},
    {CommandKind::QuadBox, "QuadBox", "[size]", -1, -1, {}},

};

struct Alias {
    std::string_view word;
    CommandKind kind;
};

// Other spellings real scripts use.
constexpr Alias kAliases[] = {
    {"Persp", CommandKind::Perspective},
    {"TransformBegin", CommandKind::PushMatrix},
    {"TransformEnd", CommandKind::PopMatrix},
    {"RenderTargetTexture", CommandKind::RenderToTexture},
};

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        auto x = static_cast<unsigned char>(a[i]);
        auto y = static_cast<unsigned char>(b[i]);
        if (std::tolower(x) != std::tolower(y)) return false;
    }
    return true;
}

}  // namespace

std::optional<CommandKind> lookupCommand(std::string_view word) {
    for (const CommandRule& r : kRules)
        if (equalsIgnoreCase(r.name, word)) return r.kind;
    for (const Alias& a : kAliases)
        if (equalsIgnoreCase(a.word, word)) return a.kind;
    return std::nullopt;
}

const CommandRule* commandRule(CommandKind kind) {
    for (const CommandRule& r : kRules)
        if (r.kind == kind) return &r;
    return nullptr;
}

std::string_view commandName(CommandKind kind) {
    const CommandRule* r = commandRule(kind);
    return r ? r->name : "Unknown";
}

const CommandRule* commandRulesBegin() { return std::begin(kRules); }
const CommandRule* commandRulesEnd() { return std::end(kRules); }

}  // namespace glimmer
