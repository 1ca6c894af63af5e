// The two classroom seed scripts (superblur.glib and bloom.glib from the Bloom
// lecture), verbatim in tests/data/lang: they write their Program uniforms on
// lines of their own, and must still parse to the commands they mean.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lang_test_util.h"

namespace glimmer {
namespace {

using test::dump;
using test::messages;
using test::parse;
using Strings = std::vector<std::string>;

std::string readData(const std::string& name) {
    std::ifstream in(std::string(GLIMMER_TEST_DATA) + "/lang/" + name, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string attached(const std::string& uniform, const std::string& program, int line) {
    return "uniform '" + uniform + "' is on a line of its own; taken as part of Program '" + program + "' (line " +
           std::to_string(line) + "); glman needs a '\\' at the end of the previous line";
}

TEST(Seeds, SuperBlur) {
    std::string text = readData("superblur.glib");
    ASSERT_FALSE(text.empty());
    auto p = parse(text, "superblur.glib");
    ASSERT_EQ(dump(p.script), (Strings{
                                  "Ortho@2:1 -1 -1 1 1",
                                  "LookAt@3:1 0 0 0.5 0 0 0 0 1 0",
                                  "Texture2D@5:1 5 'grid.bmp'",
                                  "Background@7:1 0 0 0",
                                  "Clear@8:1",
                                  "Vertex@9:1 'superblur.vert'",
                                  "Fragment@10:1 'superblur.frag'",
                                  "Program@11:1 'SuperBlur' 'uHalfSize' <0 0 11> 'ImageUnit' 5",
                                  "Scale@15:1 0.5",
                                  "QuadXY@16:1 0.2 3",
                              }));
    EXPECT_EQ(messages(p.diags), (Strings{
                                     "12:5: warning: " + attached("uHalfSize", "SuperBlur", 11),
                                     "13:5: warning: " + attached("ImageUnit", "SuperBlur", 11),
                                 }));
    EXPECT_FALSE(p.diags.hasErrors());

    ASSERT_EQ(p.diags.all().size(), 2u);
    SourceTexts src;
    src.add("superblur.glib", text);
    EXPECT_EQ(formatDiagnostic(p.diags.all()[1], src),
              "superblur.glib:13:5: warning: " + attached("ImageUnit", "SuperBlur", 11) +
                  "\n"
                  "    ImageUnit 5\n"
                  "    ^");
}

TEST(Seeds, Bloom) {
    std::string text = readData("bloom.glib");
    ASSERT_FALSE(text.empty());
    auto p = parse(text, "bloom.glib");
    ASSERT_EQ(dump(p.script), (Strings{
                                  "Ortho@2:1 -1 -1 1 1",
                                  "LookAt@3:1 0 0 0.5 0 0 0 0 1 0",
                                  "Texture2D@5:1 5 'grid.bmp'",
                                  "Texture2D@6:1 6 512 512",
                                  "RenderToTexture@7:1 6",
                                  "Background@8:1 0 0.5 0",
                                  "Clear@9:1",
                                  "Vertex@10:1 'superblur.vert'",
                                  "Fragment@11:1 'superblur.frag'",
                                  "Program@12:1 'SuperBlur' 'uHalfSize' <0 0 11> 'ImageUnit' 5",
                                  "QuadXY@16:1 0.2 3",
                                  "RenderToTexture@18:1",
                                  "Background@19:1 0 0 0",
                                  "Clear@20:1",
                                  "Ortho@21:1",
                                  "Texture2D@23:1 7 'grid.bmp'",
                                  "Vertex@24:1 'bloom.vert'",
                                  "Fragment@25:1 'bloom.frag'",
                                  "Program@26:1 'Bloom' 'BlurUnit' 6 'ImageUnit' 7 'uAdd' <0 0 4>",
                                  "QuadXY@31:1 0.2 5",
                              }));
    ASSERT_EQ(p.script.commands.size(), 20u);
    ASSERT_EQ(p.script.commands[18].args.size(), 7u);
    EXPECT_EQ(p.script.commands[4].spelled, "RenderTargetTexture");
    EXPECT_EQ(p.script.commands[18].args[6].items[2].text, "4.00");
    EXPECT_EQ(test::loc(p.script.commands[18].args[6].loc), "29:10");
    EXPECT_EQ(test::loc(p.script.commands[16].args[0].loc), "24:13");
    EXPECT_EQ(messages(p.diags), (Strings{
                                     "13:5: warning: " + attached("uHalfSize", "SuperBlur", 12),
                                     "14:5: warning: " + attached("ImageUnit", "SuperBlur", 12),
                                     "27:5: warning: " + attached("BlurUnit", "Bloom", 26),
                                     "28:5: warning: " + attached("ImageUnit", "Bloom", 26),
                                     "29:5: warning: " + attached("uAdd", "Bloom", 26),
                                 }));
    EXPECT_FALSE(p.diags.hasErrors());
}

TEST(Seeds, SuperBlurWithCrlfEndingsAndNoFinalNewlineParsesTheSame) {
    std::string text = readData("superblur.glib");
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    while (!crlf.empty() && (crlf.back() == '\n' || crlf.back() == '\r')) crlf.pop_back();
    auto a = parse(text);
    auto b = parse(crlf);
    EXPECT_EQ(dump(b.script), dump(a.script));
    EXPECT_EQ(messages(b.diags), messages(a.diags));
    ASSERT_FALSE(b.script.commands.empty());
    ASSERT_EQ(b.script.commands.back().args.size(), 2u);
    EXPECT_EQ(b.script.commands.back().args[1].text, "3.");
}

}  // namespace
}  // namespace glimmer
