// Numbers read the same in every locale (issue 18). A German locale, where
// strtod and printf use a decimal comma, read "1.5" as 1 and printed 1.5 as
// "1,5"; the lexer uses std::from_chars and so does not care. These tests
// parse the same text under "C" and under de_DE.UTF-8 set for the whole
// process (as a front end calling setlocale(LC_ALL, "") in Germany would)
// and compare the trees. tools/install-deps.sh generates the locale.
#include <cstdio>
#include <locale>
#include <stdexcept>

#include <gtest/gtest.h>

#include "lang_test_util.h"

namespace glimmer {
namespace {

using test::dump;
using test::messages;
using test::parse;

// The process's C and C++ locales set to `name` for the life of the object.
class GlobalLocale {
public:
    explicit GlobalLocale(const char* name) : old_(std::locale()) { std::locale::global(std::locale(name)); }
    ~GlobalLocale() { std::locale::global(old_); }
    GlobalLocale(const GlobalLocale&) = delete;
    GlobalLocale& operator=(const GlobalLocale&) = delete;

private:
    std::locale old_;
};

const char* kText =
    "##OpenGL GLIB\n"
    "Perspective 70\nLookAt 0 0 3.5  0 0 0  0 1 0\n"
    "Program Bloom uAdd <0. 1.5 4.> uTint {0.25 0.5 0.75 1.} uDir [1e-3 -2.5E2 +0.125]\n"
    "Scale 0,5\n"  // glman's strtod in a decimal-comma locale: a comma read as the point
    "Rotate 22.5  0 0 1\nSphere .75 40 20\n";

TEST(Locale, TheGermanLocaleIsInstalled) {
    // The comparison below would prove nothing without it: fail, never skip.
    EXPECT_NO_THROW(std::locale("de_DE.UTF-8")) << "run tools/install-deps.sh (it generates de_DE.UTF-8)";
}

TEST(Locale, AScriptParsesToTheSameTreeUnderADecimalCommaLocale) {
    auto inC = parse(kText);
    std::vector<std::string> german, germanDiags;
    {
        GlobalLocale de("de_DE.UTF-8");
        char buf[16];
        std::snprintf(buf, sizeof buf, "%.1f", 1.5);
        ASSERT_STREQ(buf, "1,5") << "the locale did not take: the test would prove nothing";
        auto p = parse(kText);
        german = dump(p.script);
        germanDiags = messages(p.diags);
    }
    EXPECT_EQ(german, dump(inC.script));
    EXPECT_EQ(germanDiags, messages(inC.diags));
    // And the values are the ones written, not the locale's reading of them.
    const auto& bloom = inC.script.commands[2].args;
    ASSERT_GE(bloom.size(), 7u);
    EXPECT_EQ(dump(bloom[2]), "<0 1.5 4>");
    EXPECT_EQ(dump(bloom[6]), "[0.001 -250 0.125]");
}

}  // namespace
}  // namespace glimmer
