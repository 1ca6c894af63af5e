// The kept translations (shader/translation_cache.h): a kept result is what
// translating gives, its warnings naming the file asked for, with nothing
// translated; any other input (one byte, another stage, another prelude) is
// translated; the text form comes back equal and a malformed one is refused
// with a reason, the cache left as it was. The page's side (the bundled
// lesson's first picture all kept, and equal to translating) is
// tests/web/opening.sh.
#include <string>

#include <gtest/gtest.h>

#include "shader/translation_cache.h"

using namespace glimmer;

namespace {

// A warning (a global const from a uniform loses its 'const', issue 37) and
// a uniform initialiser (taken out for the renderer to set), so a kept
// result carries both kinds of what translating says.
const std::string kShader =
    "#version 330 compatibility\nuniform float uK = 1.25;\nuniform vec3 uC = vec3(0.1, 2., -3.5);\n"
    "const float k2 = uK * 2.;\nvoid main() { gl_FragColor = vec4(uC * k2, 1.); }\n";

std::string printed(const Diagnostics& diags) {
    std::string out;
    for (const Diagnostic& d : diags.all())
        out += d.file + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " +
               severityName(d.severity) + ": " + d.message + "\n";
    return out;
}

struct Fresh {
    WebTranslationCache& cache = webTranslationCache();
    Fresh() { reset(); }
    ~Fresh() { reset(); }
    void reset() {
        cache.clear();
        cache.recording = false;
        cache.hits = cache.misses = 0;
    }
};

TEST(TranslationCache, AKeptResultIsTheTranslationWithItsWarningsNamingTheFileAskedFor) {
    Fresh fresh;
    Diagnostics direct;
    WebTranslation expected = translateForWeb({kShader, WebStage::Fragment, "shaders/b.frag", ""}, direct);
    ASSERT_TRUE(expected.ok) << printed(direct);
    ASSERT_EQ(direct.warningCount(), 1) << printed(direct);
    ASSERT_EQ(expected.initialValues.size(), 2u);

    fresh.cache.recording = true;
    Diagnostics recorded;
    translateForWebCached({kShader, WebStage::Fragment, "shaders/b.frag", ""}, recorded);
    fresh.cache.recording = false;
    EXPECT_EQ(printed(recorded), printed(direct));
    ASSERT_EQ(fresh.cache.size(), 1u);
    EXPECT_EQ(fresh.cache.misses, 1);

    // Through the text form, into the cache as the page loads it.
    std::string text = fresh.cache.serialize(), error;
    fresh.cache.clear();
    ASSERT_TRUE(fresh.cache.parse(text, error)) << error;
    EXPECT_EQ(fresh.cache.serialize(), text);

    Diagnostics kept;
    kept.error("script.glib", {1, 1}, "said before");  // what is there stays, first
    WebTranslation got = translateForWebCached({kShader, WebStage::Fragment, "lesson/shaders/b.frag", ""}, kept);
    EXPECT_EQ(fresh.cache.hits, 1);
    EXPECT_EQ(fresh.cache.misses, 1);
    EXPECT_TRUE(got.ok);
    EXPECT_EQ(got.text, expected.text);
    ASSERT_EQ(got.initialValues.size(), expected.initialValues.size());
    for (size_t i = 0; i < got.initialValues.size(); ++i) {
        EXPECT_EQ(got.initialValues[i].name, expected.initialValues[i].name);
        EXPECT_EQ(got.initialValues[i].type, expected.initialValues[i].type);
        EXPECT_EQ(got.initialValues[i].values, expected.initialValues[i].values);  // bit for bit
        EXPECT_EQ(got.initialValues[i].line, expected.initialValues[i].line);
        EXPECT_EQ(got.initialValues[i].col, expected.initialValues[i].col);
    }
    std::string want = "script.glib:1:1: error: said before\n" + printed(direct);
    want.replace(want.find("shaders/b.frag"), 14, "lesson/shaders/b.frag");
    EXPECT_EQ(printed(kept), want);
    EXPECT_EQ(kept.warningCount(), 1);
}

TEST(TranslationCache, AnythingButTheSameStagePreludeAndTextIsTranslated) {
    Fresh fresh;
    fresh.cache.recording = true;
    Diagnostics ignored;
    translateForWebCached({kShader, WebStage::Fragment, "b.frag", ""}, ignored);
    fresh.cache.recording = false;
    std::string oneByte = kShader;
    oneByte[oneByte.find("2.;")] = '3';
    for (const WebTranslateInput& in : {WebTranslateInput{oneByte, WebStage::Fragment, "b.frag", ""},
                                        WebTranslateInput{kShader, WebStage::Vertex, "b.frag", ""},
                                        WebTranslateInput{kShader, WebStage::Fragment, "b.frag", "#define A B\n"}}) {
        Diagnostics diags;
        WebTranslation t = translateForWebCached(in, diags);
        Diagnostics direct;
        WebTranslation d = translateForWeb(in, direct);
        EXPECT_EQ(t.text, d.text);
        EXPECT_EQ(printed(diags), printed(direct));
    }
    EXPECT_EQ(fresh.cache.hits, 0);
    EXPECT_EQ(fresh.cache.misses, 4);
    EXPECT_EQ(fresh.cache.size(), 1u);
}

TEST(TranslationCache, AResultNamingAnotherFileIsNotKept) {
    Fresh fresh;
    Diagnostic other{Severity::Warning, "other.glsl", {2, 3}, "elsewhere"};
    EXPECT_FALSE(fresh.cache.store({kShader, WebStage::Fragment, "b.frag", ""}, WebTranslation{true, "x", {}}, {other}));
    EXPECT_EQ(fresh.cache.size(), 0u);
    other.file = "b.frag";
    EXPECT_TRUE(fresh.cache.store({kShader, WebStage::Fragment, "b.frag", ""}, WebTranslation{true, "x", {}}, {other}));
    EXPECT_EQ(fresh.cache.size(), 1u);
}

TEST(TranslationCache, AMalformedFileIsRefusedWithAReasonAndTheCacheKept) {
    Fresh fresh;
    Diagnostic d{Severity::Warning, "b.frag", {2, 3}, "a message\nover two lines"};
    ASSERT_TRUE(fresh.cache.store({kShader, WebStage::Fragment, "b.frag", ""},
                                  WebTranslation{true, "es text", {{"uK", "float", {1.25f}, 2, 20}}}, {d}));
    const std::string good = fresh.cache.serialize();
    const struct {
        std::string text, reason;
    } bad[] = {
        {"", "byte 0: expected 'glimmer-web-translations 1 '"},
        {"glimmer-web-translations 2 1\n", "byte 0: expected 'glimmer-web-translations 1 '"},
        {"glimmer-web-translations 1 100001\n", "byte 27: number 100001 out of range"},
        // said as written, however long (and never overflowing)
        {"glimmer-web-translations 1 100000000000\n", "byte 27: number 100000000000 out of range"},
        {"glimmer-web-translations 1 " + std::string(40, '9') + "\n", "byte 27: number 99999999999999999999... out of range"},
        {"glimmer-web-translations 1 1\n", "byte 29: expected a number"},
        {"glimmer-web-translations 1 1\n1 1 0 0\n0:\n999:abc", "byte 40: a string runs past the end"},
        {"glimmer-web-translations 1 1\n9 1 0 0\n", "byte 29: number 9 out of range"},
        {"glimmer-web-translations 1 1\n1 1 99999 0\n", "byte 33: number 99999 out of range"},
        {good.substr(0, good.size() - 1), ""},  // cut anywhere: refused
        {good + "x", "more after the last entry"},
    };
    for (const auto& b : bad) {
        std::string error;
        EXPECT_FALSE(fresh.cache.parse(b.text, error)) << b.text;
        EXPECT_NE(error.find(b.reason), std::string::npos) << error;
        EXPECT_EQ(fresh.cache.serialize(), good);  // nothing of it taken
    }
    for (size_t cut = 0; cut < good.size(); ++cut) {
        std::string error;
        EXPECT_FALSE(fresh.cache.parse(good.substr(0, cut), error)) << cut;
        EXPECT_FALSE(error.empty());
    }
    std::string error;
    fresh.cache.clear();
    ASSERT_TRUE(fresh.cache.parse(good, error)) << error;
    Diagnostics diags;
    WebTranslation t = translateForWebCached({kShader, WebStage::Fragment, "mine.frag", ""}, diags);
    EXPECT_EQ(t.text, "es text");
    ASSERT_EQ(t.initialValues.size(), 1u);
    EXPECT_EQ(t.initialValues[0].values, std::vector<float>{1.25f});
    EXPECT_EQ(printed(diags), "mine.frag:2:3: warning: a message\nover two lines\n");
}

}  // namespace
