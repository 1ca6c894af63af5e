// Unpacking a student's zip without trusting it. Every entry is checked
// before a byte is written (names, kinds, declared sizes, how many), and
// while unpacking the bytes that really come out are counted, so an entry
// that lies about its size is caught too. Through libzip (Debian's
// libzip-dev). No GL.
#pragma once
#include <cstdint>
#include <string>

namespace glimmer {

struct UnzipLimits {
    std::uint64_t maxEntries = 2000;             // files and folders together
    std::uint64_t maxEntryBytes = 64ull << 20;   // one file, unpacked
    std::uint64_t maxTotalBytes = 256ull << 20;  // every file together, unpacked
};

// An entry's name with older Windows tools' backslashes read as the folder
// separators they meant ("week3\\bloom.glib" -> "week3/bloom.glib", issue 29);
// checked by unsafeEntryName after that, so "a\\..\\b" still leaves its folder.
std::string entryPath(const std::string& name);

// Why a name (as entryPath gives it) cannot be unpacked inside its folder
// ("is an absolute path", "leaves its folder (..)", ...), or "" when it can. Pure.
std::string unsafeEntryName(const std::string& name);

// Unpacks `zipPath` into `destDir` (made if missing). On any refusal nothing
// stays behind in destDir, and `error` is a compiler-style line naming the
// zip and the entry: "class/bob.zip: error: entry '../x' leaves its folder (..)".
bool safeUnzip(const std::string& zipPath, const std::string& destDir, const UnzipLimits& limits, std::string& error);

}  // namespace glimmer
