// A missing model's stand-in is sized to the space the script gives its
// object (issue 19): 40% of the view's height, whatever the units.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "plan/stand_in_size.h"
#include "plan_test_util.h"

namespace glimmer::test {
namespace {

TEST(StandInSize, OrthoGivesAShareOfItsHeight) {
    // Ortho -60 60: 120 units high, so 40% is a diameter of 48.
    glm::mat4 p = glm::ortho(-60.f, 60.f, -60.f, 60.f, -1000.f, 1000.f);
    EXPECT_NEAR(standInRadius(p, glm::mat4(1.f)), 24.f, 1e-3);
    // A Scale .01 around the object (a model in centimetres): 100 times more of its units.
    EXPECT_NEAR(standInRadius(p, glm::scale(glm::mat4(1.f), glm::vec3(.01f))), 2400.f, 0.5);
}

TEST(StandInSize, PerspectiveShrinksWithDistance) {
    glm::mat4 p = glm::perspective(glm::radians(50.f), 1.f, .1f, 1000.f);
    glm::mat4 v = glm::lookAt(glm::vec3(0, 0, 150), glm::vec3(0), glm::vec3(0, 1, 0));
    // At 150 units the view is 2 * 150 * tan 25 = 139.9 high: 40% is 55.96 across.
    EXPECT_NEAR(standInRadius(p, v), 150 * std::tan(glm::radians(25.f)) * .4f, 1e-2);
}

TEST(StandInSize, BehindTheEyeOrCollapsedIsAUnitSphere) {
    glm::mat4 p = glm::perspective(glm::radians(50.f), 1.f, .1f, 1000.f);
    EXPECT_EQ(standInRadius(p, glm::translate(glm::mat4(1.f), glm::vec3(0, 0, 5))), 1.f);  // behind the eye
    EXPECT_EQ(standInRadius(p, glm::scale(glm::mat4(1.f), glm::vec3(0.f))), 1.f);          // Scale 0
}

TEST(StandInSize, TheWarningSaysWhatStandsIn) {
    TempProject dir;
    PlanOptions o;
    o.standIns = true;
    Planned p = plan(dir.script(), "Ortho -60 60 -60 60\nObj dragon.obj\nWireObj dragon.obj\n", o);
    auto w = warnings(p.diags);
    ASSERT_EQ(w.size(), 2u);
    EXPECT_NE(w[0].find("cannot find model 'dragon.obj'"), std::string::npos) << w[0];
    EXPECT_NE(w[0].find("); a sphere of radius 24 stands in for it, 40% of the view's height (--stand-ins)"),
              std::string::npos) << w[0];
    EXPECT_NE(w[1].find("); a wire sphere of radius 24 stands in for it"), std::string::npos) << w[1];
    ASSERT_EQ(p.plan.meshes.size(), 2u);
    EXPECT_EQ(p.plan.meshes[0].params.size(), 1u);
    EXPECT_NEAR(p.plan.meshes[0].params[0], 24, 1e-3);
}

}  // namespace
}  // namespace glimmer::test
