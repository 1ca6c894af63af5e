// The shape table: every shape command of the language has exactly one row,
// and the rows complete commands the way glman did.
#include <gtest/gtest.h>

#include "geometry/shape_registry.h"
#include "lang/commands.h"

namespace glimmer {
namespace {

const CommandKind kShapeCommands[] = {
    CommandKind::QuadXY,     CommandKind::QuadXZ,       CommandKind::QuadYZ,    CommandKind::Sphere,
    CommandKind::Torus,      CommandKind::Box,          CommandKind::Cylinder,  CommandKind::Cone,
    CommandKind::DiskXY,     CommandKind::Teapot,       CommandKind::Obj,       CommandKind::ObjAdj,
    CommandKind::WireBox,    CommandKind::WireSphere,   CommandKind::WireTorus, CommandKind::WireCylinder,
    CommandKind::WireCone,   CommandKind::WireTeapot,   CommandKind::WireObj,   CommandKind::Triangles,
    CommandKind::LinesAdjacency, CommandKind::GlBegin,  CommandKind::PointCloud, CommandKind::JitterCloud,
    CommandKind::QuadBox,
};

TEST(ShapeRegistry, EveryShapeCommandHasARowUnderItsCanonicalSpelling) {
    for (CommandKind k : kShapeCommands) {
        const ShapeRule* rule = findShapeRule(commandName(k));
        ASSERT_NE(rule, nullptr) << commandName(k);
        EXPECT_EQ(lookupCommand(rule->name), k) << rule->name;
    }
    EXPECT_EQ(findShapeRule("Ortho"), nullptr);
    EXPECT_EQ(findShapeRule("Program"), nullptr);
}

TEST(ShapeRegistry, RowsFromNumbersBuildAndWireRowsNameTheirSolid) {
    for (CommandKind k : kShapeCommands) {
        const ShapeRule* rule = findShapeRule(commandName(k));
        if (rule->source != ShapeRule::Source::Numbers) continue;
        EXPECT_NE(rule->build, nullptr) << rule->name;
        EXPECT_LE(rule->minArgs, rule->maxArgs);
        if (!rule->wireOf.empty()) {
            const ShapeRule* solid = findShapeRule(rule->wireOf);
            ASSERT_NE(solid, nullptr) << rule->name;
            EXPECT_EQ(solid->defaults, rule->defaults) << rule->name;  // a wire shape is its solid's edges
        }
    }
}

TEST(ShapeRegistry, CompletesNumbersWithGlmanDefaults) {
    const ShapeRule& sphere = *findShapeRule("Sphere");
    EXPECT_EQ(completeShapeNumbers(sphere, {}), (std::vector<double>{1, 60, 60}));
    EXPECT_EQ(completeShapeNumbers(sphere, {2, 8}), (std::vector<double>{2, 8, 60}));
    const ShapeRule& box = *findShapeRule("Box");
    EXPECT_EQ(completeShapeNumbers(box, {3}), (std::vector<double>{3, 3, 3}));  // one number: a cube
    EXPECT_EQ(completeShapeNumbers(box, {3, 1}), (std::vector<double>{3, 1, 2}));
    EXPECT_EQ(completeShapeNumbers(*findShapeRule("QuadXY"), {0.5, 2}), (std::vector<double>{0.5, 2, 1, 1}));
}

TEST(ShapeRegistry, FlatnessFollowsTheShape) {
    EXPECT_EQ(findShapeRule("QuadXZ")->flatness, ShapeRule::Flatness::Always);
    EXPECT_EQ(findShapeRule("DiskXY")->flatness, ShapeRule::Flatness::Always);
    EXPECT_EQ(findShapeRule("Sphere")->flatness, ShapeRule::Flatness::Never);
    EXPECT_EQ(findShapeRule("Triangles")->flatness, ShapeRule::Flatness::IfPointsCoplanar);
}

}  // namespace
}  // namespace glimmer
