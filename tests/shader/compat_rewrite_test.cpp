// The compatibility rewrite (shader/compat_rewrite.h) on its own: a
// directive's words are renamed as the code's are, comments are kept as
// written, and numbers are never read as words.
#include "shader/compat_rewrite.h"

#include <gtest/gtest.h>

namespace glimmer {
namespace {

TEST(CompatRewrite, DirectivesAreRenamedCommentsAndNumbersKept) {
    const char* src = "#version 120\n#define COLOR gl_FragColor /* gl_Color */\nuniform sampler2D u;\n"
                      "void main() { COLOR = texture2D(u, vec2(1e5, 0x1Fu)); } // gl_FragColor\n";
    const CompatRewrite r = rewriteCompatBuiltins(src, CompatStage::Fragment, {});
    EXPECT_EQ(r.text, "#version 330 core\nlayout(location = 0) out vec4 glimmer_FragColor;\n#line 1\n\n"
                      "#define COLOR glimmer_FragColor /* gl_Color */\nuniform sampler2D u;\n"
                      "void main() { COLOR = texture(u, vec2(1e5, 0x1Fu)); } // gl_FragColor\n");
    EXPECT_EQ(definesOf("#define A gl_Vertex\n# define B 3\n#define F(x) x\n"),
              (std::map<std::string, std::string>{{"A", "gl_Vertex"}, {"B", "3"}}));
}

}  // namespace
}  // namespace glimmer
