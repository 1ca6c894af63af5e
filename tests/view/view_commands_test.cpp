// The viewer's scripting commands (view/view_commands.h), parsed: every
// command and its arguments, the errors word for word, --exec's split.
#include <gtest/gtest.h>

#include "view/view_commands.h"

using namespace glimmer;

namespace {

TEST(ViewCommands, ParsesEveryCommand) {
    std::string err;
    auto set = parseViewCommand("set uAdd 3.5", err);
    ASSERT_TRUE(set);
    EXPECT_EQ(set->kind, ViewCommand::Kind::Set);
    EXPECT_EQ(set->name, "uAdd");
    EXPECT_EQ(set->value, 3.5);
    EXPECT_EQ(parseViewCommand("  reload ", err)->kind, ViewCommand::Kind::Reload);
    auto save = parseViewCommand("save out.png", err);
    ASSERT_TRUE(save);
    EXPECT_EQ(save->name, "out.png");
    EXPECT_EQ(parseViewCommand("show 6", err)->unit, 6);
    EXPECT_EQ(parseViewCommand("show screen", err)->unit, -1);
    EXPECT_EQ(parseViewCommand("quit", err)->kind, ViewCommand::Kind::Quit);
    EXPECT_EQ(parseViewCommand("set uOn true", err)->value, 1.0);
    auto colour = parseViewCommand("set uColor 1,0.5,0,1", err);
    ASSERT_TRUE(colour) << err;
    EXPECT_EQ(colour->text, "1,0.5,0,1");
    EXPECT_EQ(set->text, "3.5");
    auto values = parseViewCommand("values on", err);
    ASSERT_TRUE(values) << err;
    EXPECT_EQ(values->kind, ViewCommand::Kind::Values);
    EXPECT_TRUE(values->on);
    EXPECT_FALSE(parseViewCommand("values off", err)->on);
    auto probe = parseViewCommand("probe", err);
    ASSERT_TRUE(probe) << err;
    EXPECT_EQ(probe->kind, ViewCommand::Kind::Probe);
    EXPECT_TRUE(probe->report);
    EXPECT_FALSE(parseViewCommand("probe on", err)->report);
    EXPECT_FALSE(parseViewCommand("probe off", err)->on);
    auto at = parseViewCommand("probe 100 200", err);  // a pixel of the picture, not the pointer's
    ASSERT_TRUE(at) << err;
    EXPECT_TRUE(at->report);
    EXPECT_EQ(at->x, 100);
    EXPECT_EQ(at->y, 200);
    EXPECT_EQ(parseViewCommand("probe", err)->x, -1);
    auto split = parseViewCommand("split 6 screen", err);
    ASSERT_TRUE(split) << err;
    EXPECT_EQ(split->kind, ViewCommand::Kind::Split);
    EXPECT_TRUE(split->on);
    EXPECT_EQ(split->unit, 6);
    EXPECT_EQ(split->right, -1);
    EXPECT_FALSE(parseViewCommand("split off", err)->on);
    // A watch keeps its expression as written, spaces and all.
    auto watch = parseViewCommand("watch bloom.frag:13  rgb + uAdd * rgbblur ", err);
    ASSERT_TRUE(watch) << err;
    EXPECT_EQ(watch->kind, ViewCommand::Kind::Watch);
    EXPECT_EQ(watch->text, "bloom.frag:13  rgb + uAdd * rgbblur");
    EXPECT_EQ(watch->name, "");
    auto range = parseViewCommand("watch range 0,1", err);
    ASSERT_TRUE(range) << err;
    EXPECT_EQ(range->name, "range");
    EXPECT_EQ(range->text, "0,1");
    EXPECT_EQ(parseViewCommand("watch off", err)->text, "off");
}

TEST(ViewCommands, ErrorsSayWhatIsWrong) {
    std::string err;
    EXPECT_FALSE(parseViewCommand("jump", err));
    EXPECT_EQ(err, "unknown command 'jump' (set, reload, save, show, values, probe, split, watch, where, panel, scale, help, frames, quit)");
    EXPECT_FALSE(parseViewCommand("watch   ", err));
    EXPECT_EQ(err, "usage: watch FILE:LINE EXPRESSION, watch off, or watch range LO,HI|auto");
    EXPECT_FALSE(parseViewCommand("set uAdd", err));
    EXPECT_EQ(err, "usage: set NAME VALUE");
    EXPECT_FALSE(parseViewCommand("set uAdd lots", err));
    EXPECT_EQ(err, "set uAdd: 'lots' is not a number (or numbers separated by commas)");
    EXPECT_FALSE(parseViewCommand("set uColor 1,0,", err));
    EXPECT_EQ(err, "set uColor: '1,0,' is not a number (or numbers separated by commas)");
    EXPECT_FALSE(parseViewCommand("show 40", err));
    EXPECT_EQ(err, "show: '40' is not a texture unit (0 to 31) or 'screen'");
    EXPECT_FALSE(parseViewCommand("values maybe", err));
    EXPECT_EQ(err, "usage: values on|off");
    for (const char* bad : {"probe 3", "probe 1 -2", "probe 1.5 2", "probe 1 2 3", "probe 16384 0", "probe a b"}) {
        EXPECT_FALSE(parseViewCommand(bad, err)) << bad;
        EXPECT_EQ(err, "usage: probe [on|off], or probe X Y (a pixel of the picture, top left 0 0)") << bad;
    }
    EXPECT_FALSE(parseViewCommand("scale 9", err));
    EXPECT_EQ(err, "scale: '9' is not a number from 0.5 to 4");
    EXPECT_FALSE(parseViewCommand("scale", err));
    EXPECT_EQ(err, "usage: scale 0.5..4");
    auto scale = parseViewCommand("scale 1.5", err);
    ASSERT_TRUE(scale) << err;
    EXPECT_EQ(scale->kind, ViewCommand::Kind::Scale);
    EXPECT_EQ(scale->value, 1.5);
    EXPECT_FALSE(scale->onlyAsks());
    EXPECT_TRUE(parseViewCommand("frames", err)->onlyAsks());
    EXPECT_TRUE(parseViewCommand("help", err)->onlyAsks());
    EXPECT_FALSE(parseViewCommand("split 6", err));
    EXPECT_EQ(err, "usage: split LEFT_UNIT|screen RIGHT_UNIT|screen, or split off");
    EXPECT_FALSE(parseViewCommand("split 6 99", err));
    EXPECT_EQ(err, "split: '99' is not a texture unit (0 to 31) or 'screen'");
    EXPECT_FALSE(parseViewCommand("# a comment", err));
    EXPECT_EQ(err, "");
    EXPECT_FALSE(parseViewCommand("   ", err));
    EXPECT_EQ(err, "");
}

TEST(ViewCommands, ExecSplitsAtSemicolons) {
    EXPECT_EQ(splitCommands("set uAdd 3; save a.png;quit"),
              (std::vector<std::string>{"set uAdd 3", " save a.png", "quit"}));
}

TEST(ViewCommands, WhereTakesAControlsNameWithItsSpaces) {
    std::string err;
    auto where = parseViewCommand("where  Fix range ", err);
    ASSERT_TRUE(where) << err;
    EXPECT_EQ(where->kind, ViewCommand::Kind::Where);
    EXPECT_EQ(where->name, "Fix range");
    EXPECT_TRUE(where->onlyAsks());
    EXPECT_FALSE(parseViewCommand("where", err));
    EXPECT_EQ(err, "usage: where CONTROL (a slider's uniform, Watch, Watch button, Stop, Fix range, Own range, Probe)");
}

TEST(ViewCommands, PanelOnlyAsksAndTakesNoArgument) {
    std::string err;
    auto panel = parseViewCommand("panel", err);
    ASSERT_TRUE(panel) << err;
    EXPECT_EQ(panel->kind, ViewCommand::Kind::Panel);
    EXPECT_TRUE(panel->onlyAsks());  // asking is not the user at work: the idle viewer stays idle
    EXPECT_FALSE(parseViewCommand("panel all", err));
    EXPECT_EQ(err, "usage: panel");
}

}  // namespace
