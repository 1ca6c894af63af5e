// Issue 38: the watch rewrite is one pass of the lexer and passes over its
// tokens, so a 2 MB shader of one-line functions is rewritten in time that
// grows with its size (docs/PERFORMANCE.md, "The watch on a shader of many
// functions"). The test asserts only the rewritten text; the times are
// printed for that table, never asserted (a timed test fails on a busy
// machine and passes a slow change on a fast one).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include <gtest/gtest.h>

#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"
#include "shader/watch_rewrite.h"

namespace glimmer {
namespace {

// A fragment shader of one-line functions, `bytes` long or a little more,
// as in the issue; main, on the last lines, calls the first.
std::string manyFunctions(size_t bytes, int& mainLine) {
    std::string s = "#version 120\n";
    int n = 0;
    while (s.size() < bytes) s += "float f" + std::to_string(n++) + "(float x) { return x * 2. + 1.; }\n";
    mainLine = n + 3;
    return s + "void main() {\n  float a = f0(0.25);\n  gl_FragColor = vec4(a);\n}\n";
}

// The fastest of three runs of `f`, in milliseconds.
template <typename F>
double fastestMs(F f) {
    double best = 1e30;
    for (int k = 0; k < 3; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

TEST(WatchScale, TwoMegabytesOfFunctionsAreWatchedOnTheirLine) {
    for (const size_t bytes : {size_t{256} << 10, size_t{2} << 20}) {
        int line = 0;
        const std::string src = manyFunctions(bytes, line);
        WatchedStage w;
        const double lexMs = fastestMs([&] { EXPECT_GT(lexGlsl(src).size(), src.size() / 8); });
        const double watchMs = fastestMs([&] { w = watchFragment(src, line, "a"); });
        ASSERT_TRUE(w.ok) << w.error;
        EXPECT_EQ(lineOf(w.text, line), "  float a = f0(0.25); glimmer_watch_store(a);");
        std::printf("watch rewrite of %zu bytes (%d lines): lex %.1f ms, whole rewrite %.1f ms\n", src.size(), line + 2,
                    lexMs, watchMs);
    }
}

}  // namespace
}  // namespace glimmer
