#include "shader/translation_cache.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace glimmer {

namespace {

// The text form, one entry after another after a head line:
//   glimmer-web-translations 1 COUNT
//   STAGE OK INITS SAID
//   LEN:PRELUDE
//   LEN:TEXT
//   LEN:TRANSLATION
//   LEN:NAME LEN:TYPE LINE COL N BITS...      (INITS lines; floats as their bits, exact)
//   SEVERITY LINE COL DRIVER LEN:MESSAGE      (SAID lines)
// Strings carry their length, so any byte (a newline in a message) is kept.
constexpr std::string_view kHead = "glimmer-web-translations 1 ";
// Bounds on what a file may claim, checked before anything is reserved.
constexpr std::int64_t kMaxEntries = 100000, kMaxListed = 10000, kMaxComponents = 16;

void putString(std::string& out, std::string_view s) {
    out += std::to_string(s.size());
    out += ':';
    out.append(s);
}

std::uint32_t floatBits(float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

class Reader {
public:
    explicit Reader(const std::string& text) : text_(text) {}
    std::string error;

    bool fail(const std::string& why) { return failAt(at_, why); }
    bool failAt(size_t at, const std::string& why) {
        if (error.empty()) error = "byte " + std::to_string(at) + ": " + why;
        return false;
    }
    bool literal(std::string_view s) {
        if (text_.compare(at_, s.size(), s) != 0) return fail("expected '" + std::string(s) + "'");
        at_ += s.size();
        return true;
    }
    // A decimal number in [lo, hi]: all its digits read (a long one said
    // as written, cut at 20), the value held below 10^15 so it never
    // overflows (every bound here is far below).
    bool number(std::int64_t lo, std::int64_t hi, std::int64_t& v) {
        const size_t start = at_;
        v = 0;
        while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9')
            v = std::min<std::int64_t>(v * 10 + (text_[at_++] - '0'), kTooLarge);
        if (at_ == start) return fail("expected a number");
        if (v < lo || v > hi)
            return failAt(start, "number " + text_.substr(start, std::min<size_t>(at_ - start, 20)) +
                                     (at_ - start > 20 ? "..." : "") + " out of range");
        return true;
    }
    static constexpr std::int64_t kTooLarge = 1000000000000000;
    bool string(std::string& s) {
        const size_t start = at_;
        std::int64_t n = 0;
        if (!number(0, std::int64_t(1) << 30, n) || !literal(":")) return false;
        if (std::uint64_t(n) > text_.size() - at_) return failAt(start, "a string runs past the end");
        s.assign(text_, at_, size_t(n));
        at_ += size_t(n);
        return true;
    }
    bool atEnd() const { return at_ == text_.size(); }

private:
    const std::string& text_;
    size_t at_ = 0;
};

}  // namespace

bool WebTranslationCache::find(const WebTranslateInput& in, WebTranslation& out, Diagnostics& diags) const {
    auto it = entries_.find(Key{int(in.stage), std::string(in.prelude), std::string(in.text)});
    if (it == entries_.end()) return false;
    out = it->second.result;
    for (Diagnostic d : it->second.said) {
        d.file = in.file;
        diags.add(std::move(d));
    }
    return true;
}

bool WebTranslationCache::store(const WebTranslateInput& in, const WebTranslation& result,
                                const std::vector<Diagnostic>& said) {
    Kept kept{result, said};
    for (Diagnostic& d : kept.said) {
        if (d.file != in.file) return false;
        d.file.clear();
    }
    entries_[Key{int(in.stage), std::string(in.prelude), std::string(in.text)}] = std::move(kept);
    return true;
}

std::string WebTranslationCache::serialize() const {
    std::string out(kHead);
    out += std::to_string(entries_.size()) + "\n";
    for (const auto& [key, kept] : entries_) {
        const WebTranslation& r = kept.result;
        out += std::to_string(std::get<0>(key)) + " " + (r.ok ? "1" : "0") + " " +
               std::to_string(r.initialValues.size()) + " " + std::to_string(kept.said.size()) + "\n";
        putString(out, std::get<1>(key));
        out += '\n';
        putString(out, std::get<2>(key));
        out += '\n';
        putString(out, r.text);
        out += '\n';
        for (const UniformInitializer& u : r.initialValues) {
            putString(out, u.name);
            out += ' ';
            putString(out, u.type);
            out += " " + std::to_string(u.line) + " " + std::to_string(u.col) + " " + std::to_string(u.values.size());
            for (float f : u.values) out += " " + std::to_string(floatBits(f));
            out += '\n';
        }
        for (const Diagnostic& d : kept.said) {
            out += std::to_string(int(d.severity)) + " " + std::to_string(d.loc.line) + " " +
                   std::to_string(d.loc.col) + " " + (d.fromDriver ? "1" : "0") + " ";
            putString(out, d.message);
            out += '\n';
        }
    }
    return out;
}

bool WebTranslationCache::parse(const std::string& text, std::string& error) {
    Reader r(text);
    std::map<Key, Kept> read;
    std::int64_t count = 0;
    bool ok = r.literal(kHead) && r.number(0, kMaxEntries, count) && r.literal("\n");
    for (std::int64_t e = 0; ok && e < count; ++e) {
        std::int64_t stage = 0, good = 0, inits = 0, said = 0;
        std::string prelude, source;
        Kept kept;
        ok = r.number(0, int(WebStage::TessEvaluation), stage) && r.literal(" ") && r.number(0, 1, good) &&
             r.literal(" ") && r.number(0, kMaxListed, inits) && r.literal(" ") && r.number(0, kMaxListed, said) &&
             r.literal("\n") && r.string(prelude) && r.literal("\n") && r.string(source) && r.literal("\n") &&
             r.string(kept.result.text) && r.literal("\n");
        kept.result.ok = good == 1;
        for (std::int64_t i = 0; ok && i < inits; ++i) {
            UniformInitializer u;
            std::int64_t line = 0, col = 0, n = 0;
            ok = r.string(u.name) && r.literal(" ") && r.string(u.type) && r.literal(" ") &&
                 r.number(0, INT32_MAX, line) && r.literal(" ") && r.number(0, INT32_MAX, col) && r.literal(" ") &&
                 r.number(0, kMaxComponents, n);
            for (std::int64_t k = 0; ok && k < n; ++k) {
                std::int64_t bits = 0;
                ok = r.literal(" ") && r.number(0, UINT32_MAX, bits);
                float f;
                std::uint32_t b = std::uint32_t(bits);
                std::memcpy(&f, &b, sizeof f);
                u.values.push_back(f);
            }
            ok = ok && r.literal("\n");
            u.line = int(line), u.col = int(col);
            kept.result.initialValues.push_back(std::move(u));
        }
        for (std::int64_t i = 0; ok && i < said; ++i) {
            Diagnostic d;
            std::int64_t severity = 0, line = 0, col = 0, driver = 0;
            ok = r.number(0, int(Severity::Error), severity) && r.literal(" ") && r.number(0, INT32_MAX, line) &&
                 r.literal(" ") && r.number(0, INT32_MAX, col) && r.literal(" ") && r.number(0, 1, driver) &&
                 r.literal(" ") && r.string(d.message) && r.literal("\n");
            d.severity = Severity(severity);
            d.loc = {int(line), int(col)};
            d.fromDriver = driver == 1;
            kept.said.push_back(std::move(d));
        }
        if (ok) read[Key{int(stage), std::move(prelude), std::move(source)}] = std::move(kept);
    }
    if (ok && !r.atEnd()) ok = r.fail("more after the last entry");
    if (!ok) {
        error = r.error;
        return false;
    }
    entries_ = std::move(read);
    return true;
}

WebTranslationCache& webTranslationCache() {
    static WebTranslationCache cache;
    return cache;
}

WebTranslation translateForWebCached(const WebTranslateInput& in, Diagnostics& diags) {
    WebTranslationCache& cache = webTranslationCache();
    WebTranslation out;
    if (cache.find(in, out, diags)) {
        ++cache.hits;
        return out;
    }
    ++cache.misses;
    Diagnostics said;
    out = translateForWeb(in, said);
    if (cache.recording) cache.store(in, out, said.all());
    for (const Diagnostic& d : said.all()) diags.add(d);
    return out;
}

}  // namespace glimmer
