#include <algorithm>
#include <cmath>
#include <map>

#include "assets/assets.h"
#include "util/read_file.h"
#include "geometry/shape_registry.h"

namespace glimmer {
namespace {

void meshPoints(const MeshDecl& m, std::vector<glm::vec3>& out) {
    out.clear();
    for (size_t i = 0; i + 2 < m.points.size(); i += 3)
        out.emplace_back(float(m.points[i]), float(m.points[i + 1]), float(m.points[i + 2]));
}

}  // namespace

// The shape's row (geometry/shape_registry.h) builds it; the plan has
// already filled in the defaults.
bool buildMesh(const MeshDecl& m, Mesh& mesh, std::string& error, std::uint64_t used, std::uint64_t budget) {
    const ShapeRule* rule = findShapeRule(commandName(m.shape));
    if (!rule) {
        error = "no mesh for this command";
        return false;
    }
    switch (rule->source) {
    case ShapeRule::Source::Numbers:
        mesh = rule->wireOf.empty() ? rule->build(m.params) : makeWire(rule->build(m.params));
        return true;
    case ShapeRule::Source::ObjFile: {
        // Counted before tinyobjloader allocates anything: a model has no
        // bound but the file's size (geometry/mesh.h's countObj).
        std::string text, why;
        if (!readRegularFile(m.path, kMaxInputFileBytes, text, why)) {
            error = "cannot load OBJ '" + m.path + "': it " + why;
            return false;
        }
        const ObjCounts counts = countObj(text);
        if (std::uint64_t need = used + text.size() + counts.bytes; budget > 0 && need > budget) {
            error = overMemoryBudget(need, budget);
            return false;
        }
        if (m.shape == CommandKind::Obj) return loadObjText(text, counts, m.path, mesh, error);
        Mesh solid;
        if (!loadObjText(text, counts, m.path, solid, error)) return false;
        mesh = m.shape == CommandKind::ObjAdj ? makeObjAdjacency(solid) : makeWire(solid);
        return true;
    }
    case ShapeRule::Source::Points: {
        std::vector<glm::vec3> pts;
        meshPoints(m, pts);
        if (m.shape == CommandKind::Triangles) mesh = makeTrianglesFrom(pts);
        else if (m.shape == CommandKind::LinesAdjacency) mesh = makeLinesAdjacency(pts);
        else mesh = makeImmediate(ImmediatePrimitive(int(std::lround(m.params.at(0)))), pts);
        return true;
    }
    }
    return false;
}

}  // namespace glimmer
