// The written forms of a Program's uniforms, and --set on the values.
#include <gtest/gtest.h>

#include "plan/uniform_values.h"
#include "plan_test_util.h"

namespace glimmer::test {
namespace {

using V = std::vector<std::string>;
using D = std::vector<double>;
using Form = UniformSetting::Form;

// Plans "Program P <uniforms>" (shaders in place) and returns its uniforms.
struct ProgramLine {
    explicit ProgramLine(const std::string& uniforms) {
        p = plan(dir.script(), "Vertex a.vert\nFragment a.frag\nProgram P " + uniforms + "\n");
    }
    const std::vector<UniformSetting>& uniforms() const { return p.plan.programs.at(0).uniforms; }
    TempProject dir;
    Planned p;
};

TEST(UniformForms, Range) {
    ProgramLine l("uA <0 .5 1> uB <-2, 3, 10.5>");
    EXPECT_EQ(messages(l.p.diags), V{});
    ASSERT_EQ(l.uniforms().size(), 2u);
    const UniformSetting& a = l.uniforms()[0];
    EXPECT_EQ(a.name, "uA");
    EXPECT_EQ(a.form, Form::Range);
    EXPECT_EQ(a.min, 0);
    EXPECT_EQ(a.values, D{0.5});
    EXPECT_EQ(a.max, 1);
    EXPECT_EQ(a.loc.line, 3);
    EXPECT_EQ(a.loc.col, 11);
    const UniformSetting& b = l.uniforms()[1];
    EXPECT_EQ(b.form, Form::Range);
    EXPECT_EQ(b.min, -2);
    EXPECT_EQ(b.values, D{3});
    EXPECT_EQ(b.max, 10.5);
}

TEST(UniformForms, RangeMayEqualItsEnds) {
    ProgramLine l("uA <3 3 3>");
    EXPECT_EQ(messages(l.p.diags), V{});
    ASSERT_EQ(l.uniforms().size(), 1u);
    EXPECT_EQ(l.uniforms()[0].form, Form::Range);
    EXPECT_EQ(l.uniforms()[0].values, D{3});
}

TEST(UniformForms, Bools) {
    ProgramLine l("uT <true> uF <false> u0 <0> u1 <1> uU <TRUE>");
    EXPECT_EQ(messages(l.p.diags), V{});
    ASSERT_EQ(l.uniforms().size(), 5u);
    for (const auto& u : l.uniforms()) EXPECT_EQ(u.form, Form::Bool) << u.name;
    EXPECT_EQ(l.uniforms()[0].values, D{1});
    EXPECT_EQ(l.uniforms()[1].values, D{0});
    EXPECT_EQ(l.uniforms()[2].values, D{0});
    EXPECT_EQ(l.uniforms()[3].values, D{1});
    EXPECT_EQ(l.uniforms()[4].values, D{1});
}

TEST(UniformForms, ColoursArraysAndConstants) {
    ProgramLine l("uC {1 0.5 0} uD {0.4, 1.0, 0.95, 0.25} uV [1 2 3] uW [7] ImageUnit 5 uNeg -2.5");
    EXPECT_EQ(messages(l.p.diags), V{});
    ASSERT_EQ(l.uniforms().size(), 6u);
    EXPECT_EQ(l.uniforms()[0].form, Form::Color);
    EXPECT_EQ(l.uniforms()[0].values, (D{1, 0.5, 0, 1}));  // alpha 1 added
    EXPECT_EQ(l.uniforms()[1].form, Form::Color);
    EXPECT_EQ(l.uniforms()[1].values, (D{0.4, 1.0, 0.95, 0.25}));
    EXPECT_EQ(l.uniforms()[2].form, Form::Array);
    EXPECT_EQ(l.uniforms()[2].values, (D{1, 2, 3}));
    EXPECT_EQ(l.uniforms()[3].form, Form::Array);
    EXPECT_EQ(l.uniforms()[3].values, D{7});
    EXPECT_EQ(l.uniforms()[4].name, "ImageUnit");
    EXPECT_EQ(l.uniforms()[4].form, Form::Constant);
    EXPECT_EQ(l.uniforms()[4].values, D{5});
    EXPECT_EQ(l.uniforms()[5].form, Form::Constant);
    EXPECT_EQ(l.uniforms()[5].values, D{-2.5});
}

TEST(UniformForms, DecimalCommaRangeIsASlider) {
    ProgramLine l("uA < 0,01 0.1 1.0 >");
    EXPECT_EQ(messages(l.p.diags), V{"3:16: warning: decimal comma in '0,01' read as 0.01; GLIB separates values with "
                                     "commas, so write decimals with a point"});
    ASSERT_EQ(l.uniforms().size(), 1u);
    EXPECT_EQ(l.uniforms()[0].form, Form::Range);
    EXPECT_EQ(l.uniforms()[0].min, 0.01);
    EXPECT_EQ(l.uniforms()[0].values, D{0.1});
    EXPECT_EQ(l.uniforms()[0].max, 1.0);
}

TEST(UniformForms, CommaDecimalRangeGetsTheHint) {
    // Commas only (no blank between values): not read as decimal commas.
    ProgramLine l("uA <0,01,0.1,1.0> uB <0 1 2>");
    EXPECT_EQ(messages(l.p.diags),
              V{"3:14: error: uniform 'uA': a range needs 3 values <min current max>, got 4 <0 01 0.1 1.0>; "
                "commas separate values, so write decimals with a point"});
    // The rest of the line is still read.
    ASSERT_EQ(l.uniforms().size(), 1u);
    EXPECT_EQ(l.uniforms()[0].name, "uB");
}

TEST(UniformForms, TwoValueRangeHasNoHint) {
    ProgramLine l("uA <0 1>");
    EXPECT_EQ(errors(l.p.diags), V{"uniform 'uA': a range needs 3 values <min current max>, got 2 <0 1>"});
    EXPECT_TRUE(l.uniforms().empty());
}

TEST(UniformForms, RangeOutOfOrder) {
    ProgramLine l("uA <5 1 10> uB <0 11 10>");
    EXPECT_EQ(messages(l.p.diags), (V{"3:14: error: uniform 'uA': range <5 1 10> needs min <= current <= max",
                                      "3:26: error: uniform 'uB': range <0 11 10> needs min <= current <= max"}));
    EXPECT_TRUE(l.uniforms().empty());
}

TEST(UniformForms, MissingValue) {
    ProgramLine l("uA uB 1 uC");
    EXPECT_EQ(messages(l.p.diags), (V{"3:11: error: uniform 'uA' has no value",
                                      "3:19: error: uniform 'uC' has no value"}));
    ASSERT_EQ(l.uniforms().size(), 1u);
    EXPECT_EQ(l.uniforms()[0].name, "uB");
    EXPECT_EQ(l.uniforms()[0].values, D{1});
}

TEST(UniformForms, OtherMistakes) {
    ProgramLine l("uA <2> uB {1 0} uC [1 x] uD <0 y 1> 5 6");
    EXPECT_EQ(errors(l.p.diags),
              (V{"uniform 'uA': <2> is neither a range <min current max> nor a checkbox <true>/<false>",
                 "uniform 'uB': a colour needs {r g b} or {r g b a}, got 2 values",
                 "uniform 'uC': 'x' is not a number",
                 "uniform 'uD': 'y' is not a number",
                 "expected a uniform name, found '5'", "expected a uniform name, found '6'"}));
    EXPECT_TRUE(l.uniforms().empty());
}

// ---- --set ------------------------------------------------------------------

class SetTest : public ::testing::Test {
protected:
    void SetUp() override {
        p = plan(dir.script(),
                 "Vertex a.vert\nFragment a.frag\n"
                 "Program One uLevel <0 2 10> uOn <false> ImageUnit 5 uTint {1 0 0}\n"
                 "Program Two uLevel <-1 0 1> uOn <true> uDir [1 2 3]\n");
        ASSERT_EQ(messages(p.diags), V{});
        ASSERT_EQ(p.plan.programs.size(), 2u);
    }
    TempProject dir;
    Planned p;
};

TEST_F(SetTest, StartsFromTheScript) {
    UniformValues v(p.plan);
    EXPECT_EQ(v.get(0, "uLevel"), D{2});
    EXPECT_EQ(v.get(0, "uOn"), D{0});
    EXPECT_EQ(v.get(0, "ImageUnit"), D{5});
    EXPECT_EQ(v.get(0, "uTint"), (D{1, 0, 0, 1}));
    EXPECT_EQ(v.get(1, "uLevel"), D{0});
    EXPECT_EQ(v.get(1, "uOn"), D{1});
    EXPECT_TRUE(v.get(1, "ImageUnit").empty());
}

TEST_F(SetTest, InRangeSetsEveryProgram) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_TRUE(v.applySet(p.plan, "uLevel=0.5", d));
    EXPECT_EQ(messages(d), V{});
    EXPECT_EQ(v.get(0, "uLevel"), D{0.5});
    EXPECT_EQ(v.get(1, "uLevel"), D{0.5});
    EXPECT_EQ(v.get(0, "uOn"), D{0});  // others untouched
}

TEST_F(SetTest, RangeEndsAreInRange) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_TRUE(v.applySet(p.plan, "uLevel=1", d));
    EXPECT_EQ(v.get(0, "uLevel"), D{1});
    EXPECT_EQ(v.get(1, "uLevel"), D{1});
    EXPECT_EQ(messages(d), V{});
}

TEST_F(SetTest, OutOfRangeNamesTheRange) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_FALSE(v.applySet(p.plan, "uLevel=5", d));
    ASSERT_EQ(d.all().size(), 1u);
    EXPECT_EQ(d.all()[0].file, dir.script());
    EXPECT_EQ(d.all()[0].loc.line, 4);
    EXPECT_EQ(messages(d), V{"4:13: error: --set uLevel=5 is outside the range <-1 1> of uniform 'uLevel' in Program Two"});
    EXPECT_EQ(v.get(0, "uLevel"), D{5});  // in range for One
    EXPECT_EQ(v.get(1, "uLevel"), D{0});  // kept for Two

    Diagnostics d2;
    EXPECT_FALSE(v.applySet(p.plan, "uLevel=-0.5", d2));
    EXPECT_EQ(errors(d2), V{"--set uLevel=-0.5 is outside the range <0 10> of uniform 'uLevel' in Program One"});
    EXPECT_EQ(v.get(0, "uLevel"), D{5});
    EXPECT_EQ(v.get(1, "uLevel"), D{-0.5});
}

TEST_F(SetTest, Bools) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_TRUE(v.applySet(p.plan, "uOn=true", d));
    EXPECT_EQ(v.get(0, "uOn"), D{1});
    EXPECT_EQ(v.get(1, "uOn"), D{1});
    EXPECT_TRUE(v.applySet(p.plan, "uOn=FALSE", d));
    EXPECT_EQ(v.get(0, "uOn"), D{0});
    EXPECT_TRUE(v.applySet(p.plan, "uOn=1", d));
    EXPECT_EQ(v.get(1, "uOn"), D{1});
    EXPECT_TRUE(v.applySet(p.plan, "uOn=0", d));
    EXPECT_EQ(v.get(1, "uOn"), D{0});
    EXPECT_TRUE(v.applySet(p.plan, "uOn=True", d));  // the words in any case
    EXPECT_EQ(v.get(0, "uOn"), D{1});
    EXPECT_EQ(v.get(1, "uOn"), D{1});
    EXPECT_EQ(messages(d), V{});
}

TEST_F(SetTest, NotANumber) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_FALSE(v.applySet(p.plan, "uLevel=abc", d));
    EXPECT_FALSE(v.applySet(p.plan, "uLevel=1x", d));
    EXPECT_FALSE(v.applySet(p.plan, "uLevel=", d));
    EXPECT_EQ(errors(d), (V{"'abc' in --set uLevel=abc is not a number", "'1x' in --set uLevel=1x is not a number",
                           "'' in --set uLevel= is not a number"}));
    ASSERT_FALSE(d.all().empty());
    EXPECT_EQ(d.all()[0].file, "--set");
    EXPECT_EQ(v.get(0, "uLevel"), D{2});
}

TEST_F(SetTest, NotAnAssignment) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_FALSE(v.applySet(p.plan, "uLevel", d));
    EXPECT_FALSE(v.applySet(p.plan, "=3", d));
    EXPECT_EQ(errors(d), (V{"'uLevel' is not of the form name=value", "'=3' is not of the form name=value"}));
}

TEST_F(SetTest, UnknownNameIsAnError) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_FALSE(v.applySet(p.plan, "uNope=1", d));
    EXPECT_EQ(messages(d), V{"0:0: error: no Program sets a uniform named 'uNope'"});
    ASSERT_EQ(d.all().size(), 1u);
    EXPECT_EQ(d.all()[0].file, "--set");
    Diagnostics dv;
    EXPECT_FALSE(v.applySet(p.plan, "uNope=1", dv, "--vary"));
    ASSERT_EQ(dv.all().size(), 1u);
    EXPECT_EQ(dv.all()[0].file, "--vary");
}

TEST_F(SetTest, ConstantsCannotBeSet) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_FALSE(v.applySet(p.plan, "ImageUnit=3", d));
    EXPECT_EQ(errors(d), V{"--set ImageUnit: uniform 'ImageUnit' of Program One is a constant (a texture unit or a "
                           "fixed number), not a range, checkbox, colour or vector"});
    EXPECT_EQ(v.get(0, "ImageUnit"), D{5});
}

TEST_F(SetTest, ColoursTakeThreeOrFourNumbers) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_TRUE(v.applySet(p.plan, "uTint=0,0.5,1,0.25", d));
    EXPECT_EQ(v.get(0, "uTint"), (D{0, 0.5, 1, 0.25}));
    EXPECT_TRUE(v.applySet(p.plan, "uTint=0.5,0,1", d));
    EXPECT_EQ(v.get(0, "uTint"), (D{0.5, 0, 1, 1}));  // alpha from the script
    EXPECT_EQ(messages(d), V{});
    EXPECT_FALSE(v.applySet(p.plan, "uTint=1,0", d));
    EXPECT_FALSE(v.applySet(p.plan, "uTint=1,0,x", d));
    EXPECT_EQ(errors(d), (V{"--set uTint=1,0: uniform 'uTint' of Program One is a colour and takes R,G,B or R,G,B,A",
                           "'x' in --set uTint=1,0,x is not a number"}));
    EXPECT_EQ(v.get(0, "uTint"), (D{0.5, 0, 1, 1}));
}

TEST(SetColour, RgbKeepsTheScriptsOwnAlpha) {
    ProgramLine l("uGlow {1 0 0 .25}");
    ASSERT_EQ(messages(l.p.diags), V{});
    UniformValues v(l.p.plan);
    Diagnostics d;
    EXPECT_TRUE(v.applySet(l.p.plan, "uGlow=0,1,0", d));
    EXPECT_EQ(v.get(0, "uGlow"), (D{0, 1, 0, 0.25}));
    EXPECT_EQ(messages(d), V{});
}

TEST_F(SetTest, VectorsTakeTheirLength) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_TRUE(v.applySet(p.plan, "uDir=-1,0,2.5", d));
    EXPECT_EQ(v.get(1, "uDir"), (D{-1, 0, 2.5}));
    EXPECT_FALSE(v.applySet(p.plan, "uDir=1,2", d));
    EXPECT_EQ(errors(d), V{"--set uDir=1,2: uniform 'uDir' of Program Two is a vector of 3 and takes 3 numbers "
                           "separated by commas"});
    EXPECT_EQ(v.get(1, "uDir"), (D{-1, 0, 2.5}));
}

TEST_F(SetTest, RangesTakeOneNumber) {
    UniformValues v(p.plan);
    Diagnostics d;
    EXPECT_FALSE(v.applySet(p.plan, "uOn=1,0", d));
    EXPECT_FALSE(v.applySet(p.plan, "uLevel=1,0", d, "--vary"));
    EXPECT_EQ(errors(d), (V{"--set uOn=1,0: uniform 'uOn' of Program One is a checkbox and takes one value",
                           "--set uOn=1,0: uniform 'uOn' of Program Two is a checkbox and takes one value",
                           "--vary uLevel=1,0: uniform 'uLevel' of Program One is a range and takes one number",
                           "--vary uLevel=1,0: uniform 'uLevel' of Program Two is a range and takes one number"}));
}

}  // namespace
}  // namespace glimmer::test
