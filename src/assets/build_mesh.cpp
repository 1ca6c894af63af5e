#include <algorithm>
#include <cmath>
#include <map>

#include "assets/assets.h"

namespace glimmer {
namespace {

void meshPoints(const MeshDecl& m, std::vector<glm::vec3>& out) {
    out.clear();
    for (size_t i = 0; i + 2 < m.points.size(); i += 3)
        out.emplace_back(float(m.points[i]), float(m.points[i + 1]), float(m.points[i + 2]));
}

}  // namespace

// Defaults are already filled in by the plan; counts below a shape's minimum
// are raised to it here, as glman did.
bool buildMesh(const MeshDecl& m, Mesh& mesh, std::string& error) {
    const auto& p = m.params;
    auto i = [&](size_t k) { return int(std::lround(p[k])); };
    switch (m.shape) {
    case CommandKind::QuadXY: mesh = makeQuadXY(float(p[0]), float(p[1]), i(2), i(3)); return true;
    case CommandKind::QuadXZ: mesh = makeQuadXZ(float(p[0]), float(p[1]), i(2), i(3)); return true;
    case CommandKind::QuadYZ: mesh = makeQuadYZ(float(p[0]), float(p[1]), i(2), i(3)); return true;
    case CommandKind::Sphere: mesh = makeSphere(float(p[0]), std::max(i(1), 3), std::max(i(2), 2)); return true;
    case CommandKind::Torus: mesh = makeTorus(float(p[0]), float(p[1]), std::max(i(2), 3), std::max(i(3), 3)); return true;
    case CommandKind::Box: mesh = makeBox(float(p[0]), float(p[1]), float(p[2])); return true;
    case CommandKind::Obj: return loadObj(m.path, mesh, error);
    case CommandKind::Cylinder: mesh = makeCylinder(float(p[0]), float(p[1]), std::max(i(2), 3)); return true;
    case CommandKind::Cone: mesh = makeCone(float(p[0]), float(p[1]), std::max(i(2), 3)); return true;
    case CommandKind::DiskXY: mesh = makeDiskXY(float(p[0]), std::max(i(1), 3)); return true;
    case CommandKind::Teapot: mesh = makeTeapot(float(p[0]), std::max(i(1), 1)); return true;
    case CommandKind::QuadBox: mesh = makeQuadBox(float(p[0])); return true;
    case CommandKind::PointCloud: mesh = makePointCloud(i(0), float(p[1])); return true;
    case CommandKind::JitterCloud: mesh = makeJitterCloud(i(0), float(p[1]), float(p[2])); return true;
    case CommandKind::Triangles:
    case CommandKind::LinesAdjacency:
    case CommandKind::GlBegin: {
        std::vector<glm::vec3> pts;
        meshPoints(m, pts);
        if (m.shape == CommandKind::Triangles) mesh = makeTrianglesFrom(pts);
        else if (m.shape == CommandKind::LinesAdjacency) mesh = makeLinesAdjacency(pts);
        else mesh = makeImmediate(ImmediatePrimitive(i(0)), pts);
        return true;
    }
    case CommandKind::ObjAdj:
    case CommandKind::WireObj: {
        Mesh solid;
        if (!loadObj(m.path, solid, error)) return false;
        mesh = m.shape == CommandKind::ObjAdj ? makeObjAdjacency(solid) : makeWire(solid);
        return true;
    }
    case CommandKind::WireBox:
    case CommandKind::WireSphere:
    case CommandKind::WireTorus:
    case CommandKind::WireCylinder:
    case CommandKind::WireCone:
    case CommandKind::WireTeapot: {
        static const std::map<CommandKind, CommandKind> solidOf = {
            {CommandKind::WireBox, CommandKind::Box},           {CommandKind::WireSphere, CommandKind::Sphere},
            {CommandKind::WireTorus, CommandKind::Torus},       {CommandKind::WireCylinder, CommandKind::Cylinder},
            {CommandKind::WireCone, CommandKind::Cone},         {CommandKind::WireTeapot, CommandKind::Teapot}};
        MeshDecl solidDecl = m;
        solidDecl.shape = solidOf.at(m.shape);
        Mesh solid;
        if (!buildMesh(solidDecl, solid, error)) return false;
        mesh = makeWire(solid);
        return true;
    }
    default: error = "no mesh for this command"; return false;
    }
}

}  // namespace glimmer
