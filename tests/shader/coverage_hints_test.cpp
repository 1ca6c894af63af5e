// Shader texts that vouch for a draw painting every pixel it covers: the
// plain transform as the only write of gl_Position, and no discard.
#include <gtest/gtest.h>

#include "shader/coverage_hints.h"

using namespace glimmer;

namespace {

TEST(CoverageHints, ThePlainTransformInAnySpacing) {
    EXPECT_TRUE(keepsPlainTransform("void main() {\n  vST = gl_MultiTexCoord0.st;\n"
                                    "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n}\n"));
    EXPECT_TRUE(keepsPlainTransform("void main(){gl_Position=gl_ModelViewProjectionMatrix*gl_Vertex;}"));
    EXPECT_TRUE(keepsPlainTransform("void main() { gl_Position = ftransform(); }"));
}

TEST(CoverageHints, AnythingElseIsNotVouchedFor) {
    EXPECT_FALSE(keepsPlainTransform("void main() { gl_Position = gl_ModelViewProjectionMatrix * (gl_Vertex * 0.5); }"));
    EXPECT_FALSE(keepsPlainTransform("void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                                     "  gl_Position.x += 0.1; }"));
    EXPECT_FALSE(keepsPlainTransform("void main() { }"));
    EXPECT_FALSE(keepsPlainTransform("uniform mat4 M; void main() { gl_Position = M * gl_Vertex; }"));
    // The plain transform last, after another write in a branch: not the only write.
    EXPECT_FALSE(keepsPlainTransform("uniform bool uHide; void main() { if (uHide) gl_Position = vec4(2.);\n"
                                     "  else gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }"));
}

TEST(CoverageHints, DiscardAsAWordOnly) {
    EXPECT_TRUE(mayDiscard("void main() { if (a < .5) discard; gl_FragColor = vec4(1.); }"));
    EXPECT_FALSE(mayDiscard("uniform float uDiscardBelow; void main() { gl_FragColor = vec4(uDiscardBelow); }"));
    EXPECT_FALSE(mayDiscard("void main() { gl_FragColor = vec4(1.); }"));
}

// Read through the lexer: a comment is no code, a directive's words are
// (a macro's body is code wherever it is used).
TEST(CoverageHints, CommentsAreNotCodeAndDirectivesAre) {
    EXPECT_TRUE(mayDiscard("#define KILL discard\nvoid main() { if (a < .5) KILL; }"));
    EXPECT_FALSE(mayDiscard("// never discard: it slows the tiler\nvoid main() { gl_FragColor = vec4(1.); }"));
    EXPECT_TRUE(keepsPlainTransform("void main() {\n  // gl_Position = vec4(0.);\n"
                                    "  gl_Position = /* fixed */ gl_ModelViewProjectionMatrix * gl_Vertex;\n}\n"));
    EXPECT_FALSE(keepsPlainTransform("#define MOVE gl_Position.x += .1\n"
                                     "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; MOVE; }"));
    // Which ';' ends it depends on a macro: not vouched for.
    EXPECT_FALSE(keepsPlainTransform("void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex\n"
                                     "#ifdef PLAIN\n  ;\n#else\n  * 2.;\n#endif\n}"));
}

}  // namespace
