// libFuzzer: the shader text path (issue 30) on arbitrary text: the
// #version reader, word scanning, and every rewrite and check Glimmer runs
// on a student's GLSL before the driver sees it. No GL: these are the steps
// that once used std::regex, which overflowed the stack on a long line.
#include <cstddef>
#include <cstdint>
#include <string>

#include "shader/compat_rewrite.h"
#include "shader/coverage_hints.h"
#include "shader/glsl_scan.h"
#include "shader/gs4_translate.h"
#include "shader/precision_strip.h"
#include "shader/uniform_declaration.h"
#include "shader/uninitialized_globals.h"
#include "shader/watch_rewrite.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glimmer;
    const std::string text(reinterpret_cast<const char*>(data), size);
    GlslVersion v = glslVersionOf(text);
    if (v.number < 0 || v.number > kMaxGlslVersionNumber || v.line < 0) __builtin_trap();
    std::string word = firstWordWithPrefix(text, "gl_");
    if (!word.empty() && (word.compare(0, 3, "gl_") != 0 || word.size() == 3)) __builtin_trap();
    for (CompatStage stage : {CompatStage::Vertex, CompatStage::Fragment})
        (void)rewriteCompatBuiltins(text, stage, definesOf(text));
    (void)stripPrecisionQualifiers(text);
    (void)translateGs4(text);
    (void)keepsPlainTransform(text);
    (void)mayDiscard(text);
    (void)uniformDeclarationLine(text, word.empty() ? "uAdd" : word);
    (void)globalSetByMainFirst(text, word.empty() ? "gK" : word, 1);
    // A watch at a line taken from the text's own length, of its first word.
    const int line = 1 + int(size % 64);
    WatchedStage watched = watchFragment(text, line, word.empty() ? "gl_FragCoord" : word);
    if (watched.ok && watched.text.size() < text.size()) __builtin_trap();  // a rewrite only adds
    (void)watchVertex(text, line, "x");
    (void)watchFragmentOfVertex(text);
    WatchSpec spec;
    std::string why;
    (void)parseWatchSpec(text, spec, why);
    return 0;
}
