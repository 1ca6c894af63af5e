// Driver warnings worth trusting (issue 19): the driver's messages are marked
// as the driver's, and its "used uninitialized" about a global that main sets
// before any call becomes a note saying it is a false alarm; the true one stays.
#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {

TEST(CliDriverWarnings, FalseAlarmsAreSaidToBeAndTheTrueOneStays) {
    const std::string shader = cliData("false_alarms.frag");
    auto r = runGlimmer({"check", cliData("false_alarms.glib"), "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string line8 = "vec3 shade() { return gColor * gK * vST.s; }\n";
    EXPECT_EQ(r.err, shader + ":8:23: note: the driver's warning \"`gColor' used uninitialized\" is a false alarm: "
                              "main sets the global gColor (line 11) before it calls any function\n" +
                         line8 + "                      ^\n" + shader +
                         ":8:32: note: the driver's warning \"`gK' used uninitialized\" is a false alarm: main sets "
                         "the global gK (line 10) before it calls any function\n" +
                         line8 + "                               ^\n" + shader +
                         ":14:20: warning: `t' used uninitialized [driver]\n"
                         "    gl_FragColor.r += t;\n"
                         "                   ^\n");
}

}  // namespace
}  // namespace glimmer_cli
