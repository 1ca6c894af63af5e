// The number fallbacks (util/numbers.h), used where the standard library
// has no floating-point from_chars/to_chars (Emscripten 3.1.6, the browser
// build), against the standard functions of the desktop build: the same
// value, the same end, the same error, on every shape of text a script or
// a --set can hold.
#include "util/numbers.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "util/pcg32.h"

namespace glimmer {
namespace {

const std::vector<std::string> kTexts = {
    "0", "1", "-1", "1.5", "-0.25", ".5", "-.5", "5.", "1e3", "1E-3", "2.5e+2", "1e", "1e+", "1.5x", "3;",
    "1.5.2", "12abc", "007", "0.1", "0.30000000000000004", "123456789012345678901234567890", "1e308", "1e309",
    "-1e309", "1e-400", "4.9e-324", "inf", "-inf", "Infinity", "nan", "NaN", "nan(123)", "infx", "0x1p3", "0x",
    "-0x10", "+1", " 1", "", "-", ".", "-.", "e5", "abc", "1,5", "1 2", "1-2", "1e5e5", "--1", "1(2)"};

TEST(Numbers, TheFallbackReadsAsFromCharsDoes) {
    for (const std::string& text : kTexts) {
        SCOPED_TRACE("'" + text + "'");
        const char* first = text.data();
        const char* last = first + text.size();
        double want = 42, got = 42;
        auto [wantEnd, wantEc] = std::from_chars(first, last, want);
        ParsedNumber p = detail::parseDoubleFallback(first, last, got);
        EXPECT_EQ(p.end - first, wantEnd - first);
        EXPECT_EQ(int(p.ec), int(wantEc));
        if (std::isnan(want)) EXPECT_TRUE(std::isnan(got));
        else EXPECT_EQ(got, want);  // bit-exact, and 42 where both leave it
    }
}

TEST(Numbers, TheFallbackWritesAsToCharsDoes) {
    std::vector<double> values = {0.,     -0.,     1.,      -1.,          0.5,     1.5,   0.1,
                                  1. / 3, 2. / 3,  100.,    1e5,          1e15,    1e16,  1e17,
                                  1e21,   1e22,    1e-5,    1e-7,         123.456, 6e-8,  4.9e-324,
                                  1e308,  65504.,  0.0001,  0.00001234,   12345678.9,     -2.5e-3,
                                  std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity()};
    for (double v : values) {
        char buf[64];
        auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
        ASSERT_EQ(int(ec), 0);
        EXPECT_EQ(detail::formatDoubleFallback(v), std::string(buf, ptr)) << v;
    }
}

// Any finite double: written by both, and the fallback's text read back by
// both readers to the same bits.
TEST(Numbers, TheFallbacksAgreeOnRandomBitPatterns) {
    Pcg32 rng(18);
    int compared = 0;
    for (int k = 0; k < 20000; ++k) {
        std::uint64_t bits = (std::uint64_t(rng.next()) << 32) | rng.next();
        double v = std::bit_cast<double>(bits);
        if (!std::isfinite(v)) continue;
        char buf[64];
        auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
        std::string text = detail::formatDoubleFallback(v);
        ASSERT_EQ(text, std::string(buf, ptr));
        double back = 0;
        auto p = detail::parseDoubleFallback(text.data(), text.data() + text.size(), back);
        ASSERT_EQ(int(p.ec), 0) << text;
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back), bits) << text;
        ++compared;
    }
    EXPECT_GT(compared, 19000);
}

TEST(Numbers, ReadAndWrittenIgnoreTheLocale) {
    // What the lexer is handed, through the function it calls.
    double v = 0;
    const char* t = "1.25";
    auto p = parseDouble(t, t + 4, v);
    EXPECT_EQ(int(p.ec), 0);
    EXPECT_EQ(p.end, t + 4);
    EXPECT_EQ(v, 1.25);
    EXPECT_EQ(formatDouble(1.25), "1.25");
}

}  // namespace
}  // namespace glimmer
