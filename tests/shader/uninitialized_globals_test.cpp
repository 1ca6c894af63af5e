// The driver's "used uninitialized" about a global main sets before any call
// is a false alarm; the text check says so only when it can see it (issue 19).
#include <gtest/gtest.h>

#include "shader/uninitialized_globals.h"

namespace glimmer {
namespace {

const std::string kShader = "#version 330 compatibility\n"      // 1
                            "float gK;              // set in main\n"  // 2
                            "vec3 gColor;\n"                       // 3
                            "float gLate;\n"                       // 4
                            "in vec2 vST;\n"                       // 5
                            "vec3 shade() { return gColor * gK * gLate * vST.s; }\n"  // 6
                            "void main() {\n"                      // 7
                            "    gK = 0.5;\n"                      // 8
                            "    gColor.rgb = vec3(1., .5, .2);\n" // 9
                            "    vec3 c = shade();\n"              // 10
                            "    gLate = 2.;\n"                    // 11
                            "    float t;\n"                       // 12
                            "    gl_FragColor = vec4(c * t, 1.);\n"  // 13
                            "}\n";

TEST(UninitializedGlobals, SetByMainBeforeAnyCallIsAFalseAlarm) {
    EXPECT_EQ(globalSetByMainFirst(kShader, "gK", 6), 8);
    EXPECT_EQ(globalSetByMainFirst(kShader, "gColor", 6), 9);
}

TEST(UninitializedGlobals, TheTrueOnesStay) {
    EXPECT_EQ(globalSetByMainFirst(kShader, "gLate", 6), 0);  // set after the call
    EXPECT_EQ(globalSetByMainFirst(kShader, "t", 13), 0);     // a local, read in main
    EXPECT_EQ(globalSetByMainFirst(kShader, "gK", 13), 0);    // a read in main itself
    // Set only inside an if: main may call shade() without it.
    EXPECT_EQ(globalSetByMainFirst("float g;\nfloat f() { return g; }\nvoid main() {\n"
                                   "    if (gl_FragCoord.x > 1.) { g = 1.; }\n    gl_FragColor = vec4(f());\n}\n",
                                   "g", 2),
              0);
    // Also when it is not the block's first statement: a statement inside the
    // block is none of main's own.
    EXPECT_EQ(globalSetByMainFirst("float g;\nfloat f() { return g; }\nvoid main() {\n"
                                   "    if (gl_FragCoord.x > 1.) { float a = 2.; g = a; }\n    gl_FragColor = vec4(f());\n}\n",
                                   "g", 2),
              0);
    // A uniform is never "set by main".
    EXPECT_EQ(globalSetByMainFirst("uniform float g;\nfloat f() { return g; }\nvoid main() { g = 1.; f(); }\n", "g", 2),
              0);
}

// An element set through an index that has brackets of its own is set; a
// call in a comment or a directive is no call.
TEST(UninitializedGlobals, AnIndexedElementIsSetPastCommentsAndDirectives) {
    const std::string text = "float g[2];\nint ij[2] = int[2](0, 1);\n#define CALL f()\nfloat f() { return g[0]; }\n"
                             "void main() {\n    /* f(); */ g[ij[0]] = 1.;\n    gl_FragColor = vec4(f());\n}\n";
    EXPECT_EQ(globalSetByMainFirst(text, "g", 4), 6);
}

// A brace at file scope with no parenthesis before it (a struct, an
// interface block) is no function, also when it is the last thing in the
// shader and no parenthesis follows it: the answer is the same as without it.
TEST(UninitializedGlobals, AStructAfterMainIsNoFunction) {
    const std::string text = "float g;\nfloat f() { return g; }\nvoid main() {\n    g = 1.;\n"
                             "    gl_FragColor = vec4(f());\n}\nstruct Late { float a; };\n";
    EXPECT_EQ(globalSetByMainFirst(text, "g", 2), 4);
    EXPECT_EQ(globalSetByMainFirst(text + "uniform Block { vec4 b; };\n", "g", 2), 4);
}

}  // namespace
}  // namespace glimmer
