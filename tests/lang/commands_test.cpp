#include "lang/commands.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace glimmer
