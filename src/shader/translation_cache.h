// Finished translations to GLSL ES 3.00 (shader/web_translate.h), kept so
// the page's first picture calls no glslang (issue 39).
//
// Why: in Chromium the page's open was mostly the translator's WebAssembly
// compiled lazily on its first call (1,599 functions of glslang and
// SPIRV-Cross), 0.4-0.8 s before the first picture. The bundled lesson's
// shaders are known when the page is built, so the build runs the page's
// own module once over them (src/web/make_translations.cjs, in node) and
// ships what it said beside the module (lesson-translations.txt; a packed
// lesson carries it as a data block). The page loads it before the first
// open; a shader whose text, stage and prelude equal a kept one's gets the
// kept result, diagnostics included, without translating. Anything else
// (an edit, a student's own file) is translated as before.
//
// Contract:
//   - A hit is exact: the whole input (stage, prelude, text) is compared,
//     not a hash, so no text can pass for another. The file name is not
//     part of it: the kept diagnostics name the file they were made for,
//     and a hit names the file it is asked for (the same text opened from
//     a packed lesson's folder says its own path).
//   - Only translations whose every diagnostic names the translated file
//     are kept (a message naming another file could not be re-pointed).
//   - The text form is the module's own: it is made by the module that
//     reads it (the build regenerates it at every link), so it carries no
//     translator version; parse() refuses anything malformed with a reason
//     and never reads past what it was given.
//   - Desktop builds load none: translateForWebCached is translateForWeb.
#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "lang/diagnostics.h"
#include "shader/web_translate.h"

namespace glimmer {

class WebTranslationCache {
public:
    // The kept translation of `in`: true with `out` set and the kept
    // diagnostics added to `diags` (naming in.file); false when none is kept.
    bool find(const WebTranslateInput& in, WebTranslation& out, Diagnostics& diags) const;
    // Keeps `result` and what translating said; false (nothing kept) when a
    // diagnostic names another file than in.file.
    bool store(const WebTranslateInput& in, const WebTranslation& result, const std::vector<Diagnostic>& said);

    // The text form (see the contract), and reading it back: on false,
    // `error` says what is wrong and the cache is left as it was.
    std::string serialize() const;
    bool parse(const std::string& text, std::string& error);

    std::size_t size() const { return entries_.size(); }
    void clear() { entries_.clear(); }

    // Recording: translateForWebCached keeps every translation it makes.
    bool recording = false;
    // What translateForWebCached found since the last reset.
    int hits = 0, misses = 0;

private:
    struct Kept {
        WebTranslation result;
        std::vector<Diagnostic> said;  // `file` empty: the file asked for
    };
    using Key = std::tuple<int, std::string, std::string>;  // stage, prelude, text
    std::map<Key, Kept> entries_;
};

// The process's cache (the page's module holds one).
WebTranslationCache& webTranslationCache();

// translateForWeb through the process's cache: a kept result when there is
// one, else translated (and kept when recording).
WebTranslation translateForWebCached(const WebTranslateInput& in, Diagnostics& diags);

}  // namespace glimmer
