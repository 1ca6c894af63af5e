#include "lang/commands.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace glimmer {
namespace {

TEST(Commands, EveryCanonicalNameLooksUpItsOwnKind) {
    int first = static_cast<int>(CommandKind::WindowSize);
    int last = static_cast<int>(CommandKind::QuadBox);
    for (int k = first; k <= last; ++k) {
        auto kind = static_cast<CommandKind>(k);
        std::string_view name = commandName(kind);
        EXPECT_NE(name, "Unknown") << k;
        EXPECT_EQ(lookupCommand(name), kind) << name;
    }
}

TEST(Commands, CanonicalSpellings) {
    EXPECT_EQ(commandName(CommandKind::RenderToTexture), "RenderToTexture");
    EXPECT_EQ(commandName(CommandKind::Perspective), "Perspective");
    EXPECT_EQ(commandName(CommandKind::PushMatrix), "PushMatrix");
    EXPECT_EQ(commandName(CommandKind::PopMatrix), "PopMatrix");
    EXPECT_EQ(commandName(CommandKind::Gstap), "GSTAP");
    EXPECT_EQ(commandName(CommandKind::GlBegin), "glBegin");
    EXPECT_EQ(commandName(CommandKind::WireTeapot), "WireTeapot");
    EXPECT_EQ(commandName(CommandKind::Unknown), "Unknown");
}

TEST(Commands, LookupIgnoresCase) {
    EXPECT_EQ(lookupCommand("Lookat"), CommandKind::LookAt);
    EXPECT_EQ(lookupCommand("LOOKAT"), CommandKind::LookAt);
    EXPECT_EQ(lookupCommand("texture3D"), CommandKind::Texture3D);
    EXPECT_EQ(lookupCommand("RendertoTexture"), CommandKind::RenderToTexture);
    EXPECT_EQ(lookupCommand("scale"), CommandKind::Scale);
    EXPECT_EQ(lookupCommand("gstap"), CommandKind::Gstap);
    EXPECT_EQ(lookupCommand("QUADXY"), CommandKind::QuadXY);
    EXPECT_EQ(lookupCommand("glbegin"), CommandKind::GlBegin);
}

TEST(Commands, Aliases) {
    EXPECT_EQ(lookupCommand("Persp"), CommandKind::Perspective);
    EXPECT_EQ(lookupCommand("persp"), CommandKind::Perspective);
    EXPECT_EQ(lookupCommand("TransformBegin"), CommandKind::PushMatrix);
    EXPECT_EQ(lookupCommand("TransformEnd"), CommandKind::PopMatrix);
    EXPECT_EQ(lookupCommand("RenderTargetTexture"), CommandKind::RenderToTexture);
    EXPECT_EQ(lookupCommand("rendertargettexture"), CommandKind::RenderToTexture);
}

TEST(Commands, ImmediateModeAndWireVariants) {
    EXPECT_EQ(lookupCommand("glBegin"), CommandKind::GlBegin);
    EXPECT_EQ(lookupCommand("glVertex"), CommandKind::GlVertex);
    EXPECT_EQ(lookupCommand("glEnd"), CommandKind::GlEnd);
    EXPECT_EQ(lookupCommand("WireBox"), CommandKind::WireBox);
    EXPECT_EQ(lookupCommand("WireSphere"), CommandKind::WireSphere);
    EXPECT_EQ(lookupCommand("WireTorus"), CommandKind::WireTorus);
    EXPECT_EQ(lookupCommand("WireCylinder"), CommandKind::WireCylinder);
    EXPECT_EQ(lookupCommand("WireCone"), CommandKind::WireCone);
    EXPECT_EQ(lookupCommand("WireTeapot"), CommandKind::WireTeapot);
    EXPECT_EQ(lookupCommand("WireObj"), CommandKind::WireObj);
    EXPECT_EQ(lookupCommand("ObjAdj"), CommandKind::ObjAdj);
    EXPECT_EQ(lookupCommand("LinesAdjacency"), CommandKind::LinesAdjacency);
    EXPECT_EQ(lookupCommand("NumPatchVertices"), CommandKind::NumPatchVertices);
    EXPECT_EQ(lookupCommand("TessEvaluation"), CommandKind::TessEvaluation);
}

TEST(Commands, UnknownWords) {
    EXPECT_EQ(lookupCommand("Foo"), std::nullopt);
    EXPECT_EQ(lookupCommand(""), std::nullopt);
    EXPECT_EQ(lookupCommand("Orthox"), std::nullopt);
    EXPECT_EQ(lookupCommand("Ortho "), std::nullopt);
    EXPECT_EQ(lookupCommand("uHalfSize"), std::nullopt);
    EXPECT_EQ(lookupCommand("Unknown"), std::nullopt);
}

// The command table: one row per command, found by its spelling, and every
// command documented in docs/glib.md under the spelling of its row.
TEST(CommandTable, EveryRowIsFoundByItsSpellingAndDocumented) {
    std::ifstream doc(std::string(GLIMMER_SOURCE_DIR) + "/docs/glib.md");
    std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(text.empty());
    int rows = 0;
    for (const CommandRule* r = commandRulesBegin(); r != commandRulesEnd(); ++r, ++rows) {
        EXPECT_EQ(lookupCommand(r->name), r->kind) << r->name;
        EXPECT_EQ(commandRule(r->kind), r) << r->name << " has two rows";
        EXPECT_NE(text.find(std::string(r->name)), std::string::npos) << r->name << " is not in docs/glib.md";
        if (r->minNumbers >= 0) {
            EXPECT_LE(r->minNumbers, r->maxNumbers) << r->name;
        }
    }
    EXPECT_EQ(rows, int(CommandKind::QuadBox));  // every kind but Unknown
}

TEST(CommandTable, DefaultsAreGlmans) {
    EXPECT_EQ(commandRule(CommandKind::Perspective)->defaults[0], 50);
    EXPECT_EQ(commandRule(CommandKind::Timer)->defaults[0], 10);
    EXPECT_EQ(commandRule(CommandKind::LookAt)->defaults[7], 1);  // up = +y
    EXPECT_EQ(commandRule(CommandKind::GlVertex)->defaults[3], 1);  // w
}

}  // namespace
}  // namespace glimmer
