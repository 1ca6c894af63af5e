// What the panel lists and counts of a load's diagnostics (view/viewer_state.h
// keepMessages): what `glimmer check` prints, warnings alike folded into one
// line, so the panel's count is the page's and the terminal's (issue 39: the
// seed's five uniforms on lines of their own made the panel say 6 warnings
// where the page said 2). Every error is its own entry with its place; a
// note is listed and not counted.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "view/viewer_state.h"

using namespace glimmer;

namespace {

TEST(ViewerMessages, WarningsAlikeAreOneEntryAndTheCountIsCheckPrints) {
    Diagnostics diags;
    SourceTexts sources;
    sources.add("s.glib", "Ortho -1. -1. 1. 1.\nProgram P\n  uA <0. 1. 2.>\n  uB <0. 1. 2.>\n  uC <0. 1. 2.>\n");
    diags.warning("s.glib", {1, 1}, "degenerate Ortho -1. -1. 1. 1. (left == right)");
    for (int line = 3; line <= 5; ++line)
        diags.warning("s.glib", {line, 3},
                      fmt::format("uniform 'u{}' is on a line of its own; taken as part of Program 'P' (line 2)",
                                  char('A' + line - 3)));
    diags.note("s.glib", {2, 1}, "Program 'P' starts here");
    diags.error("s.glib", {4, 3}, "no such thing");
    diags.error("s.glib", {5, 3}, "no such thing either");
    ViewerState s;
    keepMessages(s, diags, sources);

    ASSERT_EQ(s.errors.size(), 2u);
    EXPECT_EQ(s.errors[0].where, "s.glib:4");
    EXPECT_EQ(s.errors[1].where, "s.glib:5");
    EXPECT_EQ(s.errors[0].text, "s.glib:4:3: error: no such thing\n  uB <0. 1. 2.>\n  ^");
    ASSERT_EQ(s.warnings.size(), 3u);
    EXPECT_EQ(warningCount(s), 2u);
    EXPECT_EQ(s.warnings[0].text.substr(0, s.warnings[0].text.find('\n')),
              "s.glib:1:1: warning: degenerate Ortho -1. -1. 1. 1. (left == right)");
    EXPECT_EQ(s.warnings[0].where, "s.glib:1");
    EXPECT_EQ(s.warnings[1].text,
              "s.glib: warning: 3 uniforms on lines of their own were taken as part of their Program (glman needs a "
              "'\\'); -v to list them");
    EXPECT_EQ(s.warnings[1].where, "s.glib");
    EXPECT_FALSE(s.warnings[1].note);
    EXPECT_TRUE(s.warnings[2].note);
    EXPECT_EQ(s.warnings[2].where, "s.glib:2");
}

}  // namespace
