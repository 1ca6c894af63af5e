#include "lang/commands.h"

#include <array>
#include <cctype>
#include <utility>

namespace glimmer {

namespace {

struct Spelling {
    std::string_view word;
    CommandKind kind;
};

// Canonical spellings first (commandName takes the first match), then the
// aliases real scripts use.
constexpr std::array kSpellings = {
    Spelling{"WindowSize", CommandKind::WindowSize},
    Spelling{"Ortho", CommandKind::Ortho},
    Spelling{"Perspective", CommandKind::Perspective},
    Spelling{"LookAt", CommandKind::LookAt},
    Spelling{"Translate", CommandKind::Translate},
    Spelling{"Rotate", CommandKind::Rotate},
    Spelling{"Scale", CommandKind::Scale},
    Spelling{"PushMatrix", CommandKind::PushMatrix},
    Spelling{"PopMatrix", CommandKind::PopMatrix},
    Spelling{"Background", CommandKind::Background},
    Spelling{"Clear", CommandKind::Clear},
    Spelling{"Color", CommandKind::Color},
    Spelling{"LineWidth", CommandKind::LineWidth},
    Spelling{"PointSize", CommandKind::PointSize},
    Spelling{"Flat", CommandKind::Flat},
    Spelling{"Smooth", CommandKind::Smooth},
    Spelling{"Timer", CommandKind::Timer},
    Spelling{"MessageBox", CommandKind::MessageBox},
    Spelling{"GSTAP", CommandKind::Gstap},
    Spelling{"Noise2D", CommandKind::Noise2D},
    Spelling{"Noise3D", CommandKind::Noise3D},
    Spelling{"Texture2D", CommandKind::Texture2D},
    Spelling{"Texture3D", CommandKind::Texture3D},
    Spelling{"CubeMap", CommandKind::CubeMap},
    Spelling{"RenderToTexture", CommandKind::RenderToTexture},
    Spelling{"Vertex", CommandKind::Vertex},
    Spelling{"Fragment", CommandKind::Fragment},
    Spelling{"Geometry", CommandKind::Geometry},
    Spelling{"TessControl", CommandKind::TessControl},
    Spelling{"TessEvaluation", CommandKind::TessEvaluation},
    Spelling{"Program", CommandKind::Program},
    Spelling{"QuadXY", CommandKind::QuadXY},
    Spelling{"QuadXZ", CommandKind::QuadXZ},
    Spelling{"QuadYZ", CommandKind::QuadYZ},
    Spelling{"Sphere", CommandKind::Sphere},
    Spelling{"Torus", CommandKind::Torus},
    Spelling{"Box", CommandKind::Box},
    Spelling{"Cylinder", CommandKind::Cylinder},
    Spelling{"Cone", CommandKind::Cone},
    Spelling{"DiskXY", CommandKind::DiskXY},
    Spelling{"Teapot", CommandKind::Teapot},
    Spelling{"Obj", CommandKind::Obj},
    Spelling{"ObjAdj", CommandKind::ObjAdj},
    Spelling{"WireBox", CommandKind::WireBox},
    Spelling{"WireSphere", CommandKind::WireSphere},
    Spelling{"WireTorus", CommandKind::WireTorus},
    Spelling{"WireCylinder", CommandKind::WireCylinder},
    Spelling{"WireCone", CommandKind::WireCone},
    Spelling{"WireTeapot", CommandKind::WireTeapot},
    Spelling{"WireObj", CommandKind::WireObj},
    Spelling{"Triangles", CommandKind::Triangles},
    Spelling{"LinesAdjacency", CommandKind::LinesAdjacency},
    Spelling{"glBegin", CommandKind::GlBegin},
    Spelling{"glVertex", CommandKind::GlVertex},
    Spelling{"glEnd", CommandKind::GlEnd},
    Spelling{"NumPatchVertices", CommandKind::NumPatchVertices},
    Spelling{"PointCloud", CommandKind::PointCloud},
    Spelling{"JitterCloud", CommandKind::JitterCloud},
    Spelling{"QuadBox", CommandKind::QuadBox},
    // aliases
    Spelling{"Persp", CommandKind::Perspective},
    Spelling{"TransformBegin", CommandKind::PushMatrix},
    Spelling{"TransformEnd", CommandKind::PopMatrix},
    Spelling{"RenderTargetTexture", CommandKind::RenderToTexture},
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
    for (const Spelling& s : kSpellings) {
        if (equalsIgnoreCase(s.word, word)) return s.kind;
    }
    return std::nullopt;
}

std::string_view commandName(CommandKind kind) {
    for (const Spelling& s : kSpellings) {
        if (s.kind == kind) return s.word;
    }
    return "Unknown";
}

}  // namespace glimmer
