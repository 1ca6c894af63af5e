// The page's kept translations (shader/translation_cache.h): loaded before
// the first open so the bundled lesson's first picture calls no glslang,
// and made at build time by this same module, run in node over the bundled
// lesson (src/web/make_translations.cjs).
//
// Contract, for the page (src/web/page/glimmer-page.js) and the build:
//   glimmer_translations_use(path)   -> how many translations the file at
//                                       `path` holds, now in use; -1 when it
//                                       cannot be read or is malformed (the
//                                       reason in glimmer_last_output(); the
//                                       page then translates everything)
//   glimmer_translations_stats()     -> "HITS MISSES KEPT": kept results used
//                                       and shaders translated, since the
//                                       start, and how many are kept
//   glimmer_translations_record(root, out)
//                                    -> `glimmer check --web` of every .glib
//                                       under root/scripts (root the working
//                                       folder, as the page runs them), every
//                                       translation kept and written to
//                                       `out`; how many, or -1 when a script
//                                       fails its check (its messages in
//                                       glimmer_last_output(): the build stops)
#include <emscripten/emscripten.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "shader/translation_cache.h"
#include "util/read_file.h"
#include "util/write_file.h"
#include "web/page_state.h"

extern "C" int glimmer_check(const char* path);
extern "C" const char* glimmer_last_output();

namespace {
// The kept translations of a lesson are tens of kilobytes; a file past this
// is not one.
constexpr std::size_t kMaxTranslationBytes = 32u << 20;
std::string stats;
}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE int glimmer_translations_use(const char* path) {
    std::string text, error;
    glimmer::WebTranslationCache& cache = glimmer::webTranslationCache();
    if (!glimmer::readRegularFile(path ? path : "", kMaxTranslationBytes, text, error) || !cache.parse(text, error)) {
        glimmer_web::setLastOutput(std::string("the kept translations: ") + error + "\n");
        return -1;
    }
    return int(cache.size());
}

EMSCRIPTEN_KEEPALIVE const char* glimmer_translations_stats() {
    const glimmer::WebTranslationCache& cache = glimmer::webTranslationCache();
    stats = std::to_string(cache.hits) + " " + std::to_string(cache.misses) + " " + std::to_string(cache.size());
    return stats.c_str();
}

EMSCRIPTEN_KEEPALIVE int glimmer_translations_record(const char* root, const char* out) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!root || !out || chdir(root) != 0) return -1;
    std::vector<std::string> scripts;
    for (auto it = fs::recursive_directory_iterator("scripts", ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->is_regular_file() && it->path().extension() == ".glib") scripts.push_back(it->path().string());
    std::sort(scripts.begin(), scripts.end());
    glimmer::WebTranslationCache& cache = glimmer::webTranslationCache();
    cache.clear();
    cache.recording = true;
    for (const std::string& script : scripts)
        if (glimmer_check(script.c_str()) != 0) {
            cache.recording = false;
            glimmer_web::setLastOutput(script + " fails `check --web`:\n" + glimmer_last_output());
            return -1;
        }
    cache.recording = false;
    std::string error;
    const std::string text = cache.serialize();
    if (!glimmer::writeBytesReplacing(out, text.data(), text.size(), error)) {
        glimmer_web::setLastOutput(std::string(out) + ": " + error + "\n");
        return -1;
    }
    return int(cache.size());
}

}  // extern "C"
