#include "geometry/shape_registry.h"

#include <algorithm>
#include <cmath>

namespace glimmer {
namespace {

int whole(double v) { return int(std::lround(v)); }

using F = ShapeRule::Flatness;
using S = ShapeRule::Source;

Mesh quadXY(const std::vector<double>& p) { return makeQuadXY(float(p[0]), float(p[1]), whole(p[2]), whole(p[3])); }
Mesh quadXZ(const std::vector<double>& p) { return makeQuadXZ(float(p[0]), float(p[1]), whole(p[2]), whole(p[3])); }
Mesh quadYZ(const std::vector<double>& p) { return makeQuadYZ(float(p[0]), float(p[1]), whole(p[2]), whole(p[3])); }
Mesh sphere(const std::vector<double>& p) {
    return makeSphere(float(p[0]), std::max(whole(p[1]), 3), std::max(whole(p[2]), 2));
}
// glman's order is glutSolidTorus's: the tube's radius first, then the ring's.
Mesh torus(const std::vector<double>& p) {
    return makeTorus(float(p[1]), float(p[0]), std::max(whole(p[2]), 3), std::max(whole(p[3]), 3));
}
Mesh box(const std::vector<double>& p) { return makeBox(float(p[0]), float(p[1]), float(p[2])); }
Mesh cylinder(const std::vector<double>& p) { return makeCylinder(float(p[0]), float(p[1]), std::max(whole(p[2]), 3)); }
Mesh cone(const std::vector<double>& p) { return makeCone(float(p[0]), float(p[1]), std::max(whole(p[2]), 3)); }
Mesh disk(const std::vector<double>& p) { return makeDiskXY(float(p[0]), std::max(whole(p[1]), 3)); }
Mesh teapot(const std::vector<double>& p) { return makeTeapot(float(p[0]), std::max(whole(p[1]), 1)); }
Mesh quadBox(const std::vector<double>& p) { return makeQuadBox(float(p[0])); }
Mesh pointCloud(const std::vector<double>& p) { return makePointCloud(whole(p[0]), float(p[1])); }
Mesh jitterCloud(const std::vector<double>& p) { return makeJitterCloud(whole(p[0]), float(p[1]), float(p[2])); }

constexpr ShapeRule::Count kSlices{2, 3, kMaxSubdivisions, "slices"};
constexpr ShapeRule::Count kTeapotSubdivisions{1, 1, kMaxTeapotSubdivisions, "subdivisions"};

// name, source, min, max, defaults, one size for all, count, flatness, build, wire of, counts from, counts lo
const ShapeRule kShapes[] = {
    {"QuadXY", S::Numbers, 2, 4, {0, 1, 1, 1}, false, {}, F::Always, quadXY, {}, 2, 1},
    {"QuadXZ", S::Numbers, 2, 4, {0, 1, 1, 1}, false, {}, F::Always, quadXZ, {}, 2, 1},
    {"QuadYZ", S::Numbers, 2, 4, {0, 1, 1, 1}, false, {}, F::Always, quadYZ, {}, 2, 1},
    {"Sphere", S::Numbers, 0, 3, {1, 60, 60}, false, {}, F::Never, sphere, {}, 1, 2},
    // Torus [tube [ring [sides [rings]]]]: with nothing written, the torus of
    // glman's manual default "1.0 0.5" (ring 1, tube .5), as before.
    {"Torus", S::Numbers, 0, 4, {.5, 1, 20, 40}, false, {}, F::Never, torus, {}, 2, 3},
    {"Box", S::Numbers, 0, 3, {2, 2, 2}, true, {}, F::Never, box, {}},
    {"Cylinder", S::Numbers, 0, 3, {1, 1, 40}, false, kSlices, F::Never, cylinder, {}},
    {"Cone", S::Numbers, 0, 3, {1, 1, 40}, false, kSlices, F::Never, cone, {}},
    {"DiskXY", S::Numbers, 0, 2, {1, 40}, false, {1, 3, kMaxSubdivisions, "slices"}, F::Always, disk, {}},
    {"Teapot", S::Numbers, 0, 2, {1, 10}, false, kTeapotSubdivisions, F::Never, teapot, {}},
    {"QuadBox", S::Numbers, 0, 1, {1}, false, {}, F::Never, quadBox, {}},
    // glman-like: `PointCloud [count [size]]`, count points in [-size, size]^3.
    {"PointCloud", S::Numbers, 0, 2, {1000, 1}, false, {0, 1, 1000000, "count"}, F::Never, pointCloud, {}},
    // `JitterCloud [n [size [jitter]]]`: an n^3 grid filling [-size, size]^3, each point jittered.
    {"JitterCloud", S::Numbers, 0, 3, {10, 1, .5}, false, {0, 1, 100, "count"}, F::Never, jitterCloud, {}},
    {"WireBox", S::Numbers, 0, 3, {2, 2, 2}, true, {}, F::Never, box, "Box"},
    {"WireSphere", S::Numbers, 0, 3, {1, 60, 60}, false, {}, F::Never, sphere, "Sphere", 1, 2},
    {"WireTorus", S::Numbers, 0, 4, {.5, 1, 20, 40}, false, {}, F::Never, torus, "Torus", 2, 3},
    {"WireCylinder", S::Numbers, 0, 3, {1, 1, 40}, false, kSlices, F::Never, cylinder, "Cylinder"},
    {"WireCone", S::Numbers, 0, 3, {1, 1, 40}, false, kSlices, F::Never, cone, "Cone"},
    {"WireTeapot", S::Numbers, 0, 2, {1, 10}, false, kTeapotSubdivisions, F::Never, teapot, "Teapot"},
    // Built from points the script lists, or from a file.
    {"Triangles", S::Points, 0, 0, {}, false, {}, F::IfPointsCoplanar, nullptr, {}},
    {"LinesAdjacency", S::Points, 0, 0, {}, false, {}, F::Never, nullptr, {}},
    {"glBegin", S::Points, 0, 0, {}, false, {}, F::IfPointsCoplanar, nullptr, {}},
    {"Obj", S::ObjFile, 0, 0, {}, false, {}, F::Never, nullptr, {}},
    {"ObjAdj", S::ObjFile, 0, 0, {}, false, {}, F::Never, nullptr, {}},
    {"WireObj", S::ObjFile, 0, 0, {}, false, {}, F::Never, nullptr, "Obj"},
};

}  // namespace

const ShapeRule* findShapeRule(std::string_view name) {
    for (const auto& r : kShapes)
        if (r.name == name) return &r;
    return nullptr;
}

std::vector<double> completeShapeNumbers(const ShapeRule& rule, const std::vector<double>& written) {
    std::vector<double> out(rule.defaults.begin(), rule.defaults.begin() + std::ptrdiff_t(rule.maxArgs));
    for (size_t i = 0; i < written.size() && i < out.size(); ++i) out[i] = written[i];
    if (rule.oneSizeForAll && written.size() == 1) std::fill(out.begin(), out.end(), written[0]);
    return out;
}

}  // namespace glimmer
