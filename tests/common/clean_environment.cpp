// Linked into every test program: before main, unsets the environment
// variables that change what Glimmer does, so no test's outcome depends on
// the shell it was started from (issue 18). A GLIMMER_TTY=1, GLIMMER_FONT or
// GLIMMER_SLICE_MS left in a developer's environment made tests fail that
// pass in CI; the children the CLI and viewer tests start inherit the clean
// environment too. A test that needs one of them sets it itself.
//
// Kept: GLIMMER_TEST_BACKENDS, how a GPU machine chooses the backend the
// render tests run on (docs/architecture.md), and GLIMMER_UPDATE_EXPECTED,
// which the Golden tests refuse with a message (tests/glman/golden_test.cpp:
// the pictures are rewritten only by tools/update-golden.sh).
#include <cstdlib>
#include <initializer_list>

namespace {

const bool kCleaned = [] {
    for (const char* name :
         {"GLIMMER_TTY", "GLIMMER_FONT", "GLIMMER_SLICE_MS", "GLIMMER_DATA_DIR", "GLIMMER_DRIVER_SHADER_CACHE",
          "GLIMMER_TEST_FAULT"})
        ::unsetenv(name);
    return true;
}();

}  // namespace
