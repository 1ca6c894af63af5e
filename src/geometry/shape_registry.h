// One row per GLIB shape command, in the spirit of clox's rules[]: how many
// numbers it takes, glman's defaults for the ones left out, which numbers
// are counts and their bounds, how its vertex arrays are built, and whether
// it can hide part of itself. The plan reads a row to check and complete a
// command; the CPU load step (assets/) builds the mesh from the same row.
//
// A new shape is one row here plus its builder (geometry/*.cpp); the
// command's spelling goes in lang/commands.cpp.
#pragma once
#include <array>
#include <string_view>
#include <vector>

#include "geometry/mesh.h"

namespace glimmer {

// The most slices, stacks, rings or subdivisions of one shape (and 300 for
// the teapot: 32 patches of (n+1)^2 vertices each); plan/limits.h lists
// every bound an untrusted script meets.
constexpr double kMaxSubdivisions = 1000;
constexpr double kMaxTeapotSubdivisions = 300;

struct ShapeRule {
    // A number of the command that must be a whole number in [lo, hi];
    // `what` names it in the error ("slices", "subdivisions", "count").
    struct Count {
        int arg = -1;  // -1: none
        double lo = 1, hi = 1;
        const char* what = "";
    };
    enum class Flatness { Never, Always, IfPointsCoplanar };
    enum class Source { Numbers, Points, ObjFile };

    std::string_view name;           // the command's canonical spelling: "Sphere"
    Source source = Source::Numbers;
    size_t minArgs = 0, maxArgs = 0; // Numbers: how many may be written
    std::array<double, 4> defaults{};  // for the numbers left out
    bool oneSizeForAll = false;      // Box: one number is the size every way
    Count count;
    Flatness flatness = Flatness::Never;
    // Numbers: builds the solid from the completed numbers. Counts below a
    // shape's minimum are raised to it, as glman did.
    Mesh (*build)(const std::vector<double>& numbers) = nullptr;
    std::string_view wireOf;         // "Sphere" for WireSphere: the wireframe of that row's solid
    // Subdivision counts from this argument on (QuadXY's nx ny, Sphere's
    // slices stacks, Torus's sides rings): whole numbers from countsLo to
    // kMaxSubdivisions, checked before anything converts them. -1: none.
    int countsFrom = -1;
    double countsLo = 1;
};

// The row of a shape command (by its canonical spelling), or null.
const ShapeRule* findShapeRule(std::string_view name);

// The numbers of a command with the defaults filled in (`written` were given).
std::vector<double> completeShapeNumbers(const ShapeRule& rule, const std::vector<double>& written);

}  // namespace glimmer
