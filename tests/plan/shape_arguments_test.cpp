// Every shape's arguments in glman's order (glman's manual, December 2011,
// "Creating Geometry"): a one-line script is planned, its mesh built from the
// plan's numbers by the shape's row, and the mesh's extents checked, so a
// swapped pair of arguments shows as a wrong box.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "geometry/shape_registry.h"
#include "lang/commands.h"
#include "plan_test_util.h"

namespace glimmer::test {
namespace {

using V = std::vector<std::string>;

struct Extents {
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{std::numeric_limits<float>::lowest()};
};

class ShapeArguments : public ::testing::Test {
protected:
    // The extents of the one shape `line` draws; its diagnostics in `diags`.
    Extents extentsOf(const std::string& line, V* diags = nullptr) {
        Planned p = plan(dir.script(), line + "\n");
        if (diags) *diags = messages(p.diags);
        else EXPECT_EQ(messages(p.diags), V{}) << line;
        Extents e;
        if (p.plan.meshes.size() != 1) {
            ADD_FAILURE() << line << ": " << p.plan.meshes.size() << " meshes";
            return e;
        }
        const MeshDecl& m = p.plan.meshes[0];
        const ShapeRule* rule = findShapeRule(commandName(m.shape));
        if (!rule || !rule->build) {
            ADD_FAILURE() << line << ": no builder";
            return e;
        }
        for (const MeshVertex& v : rule->build(m.params).vertices) {
            e.lo = glm::min(e.lo, v.position);
            e.hi = glm::max(e.hi, v.position);
        }
        return e;
    }
    TempProject dir;
};

#define EXPECT_EXTENTS(e, x0, x1, y0, y1, z0, z1, eps)                                                           \
    do {                                                                                                          \
        EXPECT_NEAR((e).lo.x, x0, eps); EXPECT_NEAR((e).hi.x, x1, eps); EXPECT_NEAR((e).lo.y, y0, eps);           \
        EXPECT_NEAR((e).hi.y, y1, eps); EXPECT_NEAR((e).lo.z, z0, eps); EXPECT_NEAR((e).hi.z, z1, eps);           \
    } while (0)

// glman's example `Torus 0.3 0.8` is a ring: a tube of radius .3 around a ring
// of radius .8 (glutSolidTorus's order), 1.1 across each way, .3 thick.
TEST_F(ShapeArguments, TorusIsTubeRadiusThenRingRadius) {
    Extents e = extentsOf("Torus 0.3 0.8 24 48");
    EXPECT_EXTENTS(e, -1.1, 1.1, -1.1, 1.1, -.3, .3, 1e-3);
    Extents w = extentsOf("WireTorus 0.3 0.8 24 48");
    EXPECT_EXTENTS(w, -1.1, 1.1, -1.1, 1.1, -.3, .3, 1e-3);
    // Nothing written: the manual's default torus (ring 1, tube .5).
    Extents d = extentsOf("Torus");
    EXPECT_EXTENTS(d, -1.5, 1.5, -1.5, 1.5, -.5, .5, 1e-2);
}

TEST_F(ShapeArguments, ATubeWiderThanItsRingIsDrawnAsWrittenAndSaidSo) {
    V diags;
    Extents e = extentsOf("Torus 0.8 0.3", &diags);
    EXPECT_NEAR(e.hi.z, .8, 1e-2);  // read as written: a tube of radius .8
    EXPECT_EQ(diags, (V{"1:7: warning: Torus read in glman's order (tube radius, then ring radius): a tube of radius 0.8 "
                        "around a ring of radius 0.3, which has no hole; for a ring write 'Torus 0.3 0.8'"}));
    extentsOf("WireTorus 1.5", &diags);  // the ring's default radius is 1
    EXPECT_EQ(diags, (V{"1:11: warning: WireTorus read in glman's order (tube radius, then ring radius): a tube of "
                        "radius 1.5 around a ring of radius 1, which has no hole; for a ring write 'WireTorus 1 1.5'"}));
}

TEST_F(ShapeArguments, SphereIsRadiusSlicesStacks) {
    Extents e = extentsOf("Sphere 2 16 8");
    EXPECT_EXTENTS(e, -2, 2, -2, 2, -2, 2, 1e-3);
}

TEST_F(ShapeArguments, BoxIsItsThreeSideLengths) {
    Extents e = extentsOf("Box 1 2 3");
    EXPECT_EXTENTS(e, -.5, .5, -1, 1, -1.5, 1.5, 1e-5);
    Extents d = extentsOf("WireBox");  // [2 2 2]
    EXPECT_EXTENTS(d, -1, 1, -1, 1, -1, 1, 1e-5);
}

// Cylinder and Cone: radius, then height (along +Y from y = 0).
TEST_F(ShapeArguments, CylinderAndConeAreRadiusThenHeight) {
    for (const char* line : {"Cylinder 0.5 2 4", "Cone 0.5 2 4", "WireCylinder 0.5 2 4", "WireCone 0.5 2 4"}) {
        SCOPED_TRACE(line);
        Extents e = extentsOf(line);  // 4 slices put vertices on +-X and +-Z
        EXPECT_EXTENTS(e, -.5, .5, 0, 2, -.5, .5, 1e-5);
    }
}

TEST_F(ShapeArguments, QuadsAreTheirPlaneThenTheirHalfSize) {
    EXPECT_EXTENTS(extentsOf("QuadXY 0.2 3"), -3, 3, -3, 3, .2, .2, 1e-5);
    EXPECT_EXTENTS(extentsOf("QuadXZ 0.2 3"), -3, 3, .2, .2, -3, 3, 1e-5);
    EXPECT_EXTENTS(extentsOf("QuadYZ 0.2 3"), .2, .2, -3, 3, -3, 3, 1e-5);
}

TEST_F(ShapeArguments, DiskAndTeapotDefaultsAreUnitSized) {
    EXPECT_EXTENTS(extentsOf("DiskXY"), -1, 1, -1, 1, 0, 0, 1e-3);
    Extents t = extentsOf("Teapot");
    EXPECT_GT(t.hi.x - t.lo.x, 2.f);  // glutSolidTeapot(1) spans about 3 across
    EXPECT_LT(t.hi.x - t.lo.x, 4.f);
}

}  // namespace
}  // namespace glimmer::test
