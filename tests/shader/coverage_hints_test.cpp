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

}  // namespace
