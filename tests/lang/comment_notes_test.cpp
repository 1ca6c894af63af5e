// The `##` block above a line: what a teacher wrote about a pass.
#include "lang/comment_notes.h"

#include <gtest/gtest.h>

namespace glimmer {
namespace {

const char* kScript =
    "##OpenGL GLIB\n"          // 1: glman's header, never a note
    "Ortho -1 1 -1 1\n"        // 2
    "\n"                       // 3
    "## Blur: every texel becomes the average\n"  // 4
    "##   of its neighbours (a cone of weights).\n"  // 5
    "Program Blur\r\n"         // 6
    "# one mark: not a note\n" // 7
    "Program Plain\n"          // 8
    "##\n"                     // 9
    "Program AfterEmpty\n";    // 10

TEST(CommentNotes, TheBlockRightAboveTheLineWithoutItsMarks) {
    EXPECT_EQ(commentNoteAbove(kScript, 6), "Blur: every texel becomes the average\n  of its neighbours (a cone of weights).");
}

TEST(CommentNotes, NoBlockNoNote) {
    EXPECT_EQ(commentNoteAbove(kScript, 8), "");   // a single # is an ordinary comment
    EXPECT_EQ(commentNoteAbove(kScript, 2), "");   // the header is not a note
    EXPECT_EQ(commentNoteAbove(kScript, 1), "");
    EXPECT_EQ(commentNoteAbove(kScript, 99), "");  // past the end
    EXPECT_EQ(commentNoteAbove(kScript, 10), "");  // an empty ## line says nothing
}

}  // namespace
}  // namespace glimmer
