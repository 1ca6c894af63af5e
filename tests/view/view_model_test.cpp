// The viewer's decisions that depend only on the plan, checked on the real
// scripts: which scenes the mouse may turn, how passes and merged uniforms
// are named, the layout of picture and panel, save names, the help text.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "lang/parser.h"
#include "view/view_commands.h"
#include "view/view_model.h"

using namespace glimmer;
namespace fs = std::filesystem;

namespace {

Plan planOf(const std::string& rel) {
    fs::path file = fs::path(GLIMMER_SOURCE_DIR) / rel;
    std::ifstream f(file);
    std::stringstream text;
    text << f.rdbuf();
    Diagnostics diags;
    Script script = parseScript(file.string(), text.str(), diags);
    Plan plan = buildPlan(script, {}, diags);
    EXPECT_FALSE(diags.hasErrors()) << rel;
    return plan;
}

TEST(SceneTurns, FlatPostProcessesDoNotTurn) {
    EXPECT_FALSE(sceneTurns(planOf("scripts/bloom.glib")));
    EXPECT_FALSE(sceneTurns(planOf("scripts/bloom/kawase.glib")));
    EXPECT_FALSE(sceneTurns(planOf("scripts/superblur.glib")));
}

TEST(SceneTurns, PerspectiveSceneWithShapesTurns) { EXPECT_TRUE(sceneTurns(planOf("scripts/shapes.glib"))); }

TEST(PassName, NamesTheProgramItsLineAndWhereItDraws) {
    Plan p = planOf("scripts/bloom.glib");
    ASSERT_EQ(p.passes.size(), 2u);
    EXPECT_EQ(passName(p, 0), "SuperBlur (line 12) -> unit 6");
    EXPECT_EQ(passName(p, 1), "Bloom (line 26) -> screen");
}

TEST(MergedUniforms, KawaseEightOffsetsAreOneControl) {
    Plan p = planOf("scripts/bloom/kawase.glib");
    auto controls = mergedUniforms(p);
    int offsets = 0;
    for (const auto& c : controls)
        if (c.name == "uOffset") {
            ++offsets;
            EXPECT_EQ(c.programs.size(), 8u);
            EXPECT_EQ(c.label(), "uOffset - 8 passes");
        }
    EXPECT_EQ(offsets, 1);
    // Split again: one control per Program.
    int split = 0;
    for (const auto& c : mergedUniforms(p, {"uOffset"}))
        if (c.name == "uOffset") {
            ++split;
            EXPECT_EQ(c.programs.size(), 1u);
            EXPECT_EQ(c.label(), "uOffset");
        }
    EXPECT_EQ(split, 8);
}

TEST(MergedUniforms, DifferentRangesStayApart) {
    Plan p;
    p.programs.resize(2);
    p.programs[0].uniforms.push_back({"u", {}, UniformSetting::Form::Range, {1}, 0, 2});
    p.programs[1].uniforms.push_back({"u", {}, UniformSetting::Form::Range, {1}, 0, 5});
    EXPECT_EQ(mergedUniforms(p).size(), 2u);
    p.programs[1].uniforms[0].max = 2;
    EXPECT_EQ(mergedUniforms(p).size(), 1u);
}

TEST(SaveNames, PicksTheFirstFreeNumber) {
    fs::path dir = fs::temp_directory_path() / ("glimmer_names_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string stem = (dir / "glimmer").string();
    EXPECT_EQ(nextFreeName(stem, ".png"), stem + "-001.png");
    std::ofstream(stem + "-001.png") << "x";
    std::ofstream(stem + "-002.png") << "x";
    EXPECT_EQ(nextFreeName(stem, ".png"), stem + "-003.png");
    fs::remove_all(dir);
}

TEST(SaveAtSize, KeepsThePicturesAspect) {
    int w = 0, h = 0;
    sizeWithAspect(600, 600, 1920, w, h);
    EXPECT_EQ(w, 1920);
    EXPECT_EQ(h, 1920);
    sizeWithAspect(800, 450, 1920, w, h);
    EXPECT_EQ(w, 1920);
    EXPECT_EQ(h, 1080);
    sizeWithAspect(300, 400, 1920, w, h);
    EXPECT_EQ(w, 1440);
    EXPECT_EQ(h, 1920);
}

TEST(WindowLayout, PanelBesideThePictureAndHidden) {
    WindowLayout l = layoutWindow(600, 600, true, 380, 900, 1000);
    EXPECT_EQ(l.windowW, 980);
    EXPECT_EQ(l.windowH, 900);
    EXPECT_EQ(l.panelX, 600);
    l = layoutWindow(600, 600, true, 380, 1400, 1000);
    EXPECT_EQ(l.windowH, 1000);  // the panel scrolls past the screen's height
    l = layoutWindow(600, 600, false, 380, 900, 1000);
    EXPECT_EQ(l.windowW, 600);
    EXPECT_EQ(l.windowH, 600);
}

// Every command the parser takes has a line in the help, and nothing else does.
TEST(Help, ListsEveryCommandOnALineOfItsOwn) {
    std::string help = helpText();
    std::string err;
    for (const char* word : {"set", "reload", "save", "show", "values", "probe", "split", "help", "quit"}) {
        EXPECT_NE(help.find(std::string("\n  ") + word + " "), std::string::npos) << word;
    }
    for (const char* key : {"space", "H ", "F ", "R ", "0 ", "S ", "Q, Esc"}) EXPECT_NE(help.find(key), std::string::npos) << key;
    auto h = parseViewCommand("help", err);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->kind, ViewCommand::Kind::Help);
    EXPECT_FALSE(parseViewCommand("help me", err));
    EXPECT_EQ(err, "usage: help");
}

// The panel follows the monitor's content scale (GLFW's; Xvfb always says
// 1) unless --ui-scale is given; a scale below 1 is never used.
TEST(UiScale, OptionElseTheMonitorsContentScale) {
    EXPECT_EQ(chooseUiScale(0, 1.f, 1.f), 1.f);      // Xvfb, a plain monitor
    EXPECT_EQ(chooseUiScale(0, 2.f, 2.f), 2.f);      // a HiDPI monitor
    EXPECT_EQ(chooseUiScale(0, 1.25f, 1.5f), 1.5f);  // the larger of the two
    EXPECT_EQ(chooseUiScale(0, 0.75f, 0.75f), 1.f);  // never smaller than 1
    EXPECT_EQ(chooseUiScale(0, 0.f, 0.f), 1.f);      // a monitor that reports nothing
    EXPECT_EQ(chooseUiScale(1.5, 2.f, 2.f), 1.5f);   // --ui-scale wins
    EXPECT_EQ(chooseUiScale(2, 1.f, 1.f), 2.f);
}

}  // namespace
