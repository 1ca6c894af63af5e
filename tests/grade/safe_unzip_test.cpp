// Hostile zips are refused before anything is written, each with a message
// naming the entry; a plain one unpacks. The zips are made here with
// libzip, and the lying one by patching a real one's size fields.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zip.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/test_folder.h"
#include "grade/safe_unzip.h"

namespace glimmer {
namespace {
namespace fs = std::filesystem;

struct Entry {
    std::string name;
    std::string data;
    bool symlink = false;
};

std::string makeZip(const fs::path& path, const std::vector<Entry>& entries) {
    int err = 0;
    zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
    EXPECT_NE(z, nullptr);
    for (const auto& e : entries) {
        zip_source_t* src = zip_source_buffer(z, e.data.data(), e.data.size(), 0);
        zip_int64_t i = zip_file_add(z, e.name.c_str(), src, ZIP_FL_ENC_UTF_8);
        EXPECT_GE(i, 0) << zip_strerror(z);
        if (e.symlink) zip_file_set_external_attributes(z, zip_uint64_t(i), 0, ZIP_OPSYS_UNIX, (S_IFLNK | 0777) << 16);
    }
    EXPECT_EQ(zip_close(z), 0);
    return path.string();
}

std::string unzipError(const std::string& zip, const fs::path& dest, UnzipLimits limits = {}) {
    std::string error;
    EXPECT_FALSE(safeUnzip(zip, dest.string(), limits, error));
    EXPECT_FALSE(fs::exists(dest)) << "a refused zip left files behind";
    return error;
}

TEST(SafeUnzip, APlainZipUnpacksWithItsFolders) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "alice.zip", {{"hw/bloom.glib", "Ortho -1 1 -1 1\n"}, {"hw/s.frag", "void main(){}"}});
    std::string error;
    ASSERT_TRUE(safeUnzip(zip, (t.path / "out").string(), {}, error)) << error;
    std::ifstream f(t.path / "out/hw/bloom.glib");
    std::string line;
    std::getline(f, line);
    EXPECT_EQ(line, "Ortho -1 1 -1 1");
    EXPECT_TRUE(fs::is_regular_file(t.path / "out/hw/s.frag"));
}

// A zip from an older Windows tool, its folders written with backslashes:
// unpacked into those folders, not refused whole (issue 29).
TEST(SafeUnzip, BackslashesAreFolders) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "bob.zip", {{"hw\\bloom.glib", "Ortho -1 1 -1 1\n"}, {"hw\\shaders\\s.frag", "x"}});
    std::string error;
    ASSERT_TRUE(safeUnzip(zip, (t.path / "out").string(), {}, error)) << error;
    EXPECT_TRUE(fs::is_regular_file(t.path / "out/hw/bloom.glib"));
    EXPECT_TRUE(fs::is_regular_file(t.path / "out/hw/shaders/s.frag"));
    EXPECT_EQ(unzipError(makeZip(t.path / "evil.zip", {{"..\\evil.glib", "x"}}), t.path / "evil"),
              (t.path / "evil.zip").string() + ": error: entry '../evil.glib' leaves its folder (..); nothing unpacked");
}

TEST(SafeUnzip, APathLeavingItsFolderIsRefused) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "bob.zip", {{"ok.glib", "x"}, {"hw/../../x", "evil"}});
    EXPECT_EQ(unzipError(zip, t.path / "out"), zip + ": error: entry 'hw/../../x' leaves its folder (..); nothing unpacked");
    EXPECT_FALSE(fs::exists(t.path / "x"));
}

TEST(SafeUnzip, AnAbsolutePathIsRefused) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "bob.zip", {{"/tmp/glimmer-evil", "evil"}});
    EXPECT_EQ(unzipError(zip, t.path / "out"), zip + ": error: entry '/tmp/glimmer-evil' is an absolute path; nothing unpacked");
}

TEST(SafeUnzip, ASymbolicLinkIsRefused) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "bob.zip", {{"passwd", "/etc/passwd", true}});
    EXPECT_EQ(unzipError(zip, t.path / "out"), zip + ": error: entry 'passwd' is a symbolic link; nothing unpacked");
}

TEST(SafeUnzip, TooManyEntriesAreRefusedBeforeAnyIsRead) {
    testing::TestFolder t("unzip");
    std::vector<Entry> many;
    for (int i = 0; i < 11; ++i) many.push_back({"f" + std::to_string(i), "x"});
    auto zip = makeZip(t.path / "bob.zip", many);
    UnzipLimits limits;
    limits.maxEntries = 10;
    EXPECT_EQ(unzipError(zip, t.path / "out", limits),
              zip + ": error: it holds 11 entries, more than the 10 allowed; nothing unpacked");
}

TEST(SafeUnzip, ABombByDeclaredSizeIsRefusedBeforeUnpacking) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "bob.zip", {{"zeros", std::string(3 << 20, '\0')}});
    EXPECT_LT(fs::file_size(zip), 100000u);  // it really is a bomb: 3 MiB from a few KiB
    UnzipLimits limits;
    limits.maxEntryBytes = 1 << 20;
    EXPECT_EQ(unzipError(zip, t.path / "out", limits),
              zip + ": error: entry 'zeros' declares 3145728 bytes unpacked, more than the 1048576 allowed for one "
                    "file; nothing unpacked");
    limits.maxEntryBytes = 4 << 20;
    limits.maxTotalBytes = 5 << 20;
    auto two = makeZip(t.path / "two.zip", {{"a", std::string(3 << 20, '\0')}, {"b", std::string(3 << 20, '\0')}});
    EXPECT_EQ(unzipError(two, t.path / "out", limits),
              two + ": error: entry 'b' brings the unpacked size to 6291456 bytes, more than the 5242880 allowed; "
                    "nothing unpacked");
}

// A zip whose entry says it unpacks to 100 bytes and unpacks to 1 MiB.
TEST(SafeUnzip, ABombByActualSizeIsStoppedWhileUnpacking) {
    testing::TestFolder t("unzip");
    auto zip = makeZip(t.path / "liar.zip", {{"zeros", std::string(1 << 20, '\0')}});
    std::vector<char> bytes;
    {
        std::ifstream in(zip, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    auto put32 = [&](size_t at, std::uint32_t v) {
        for (int k = 0; k < 4; ++k) bytes[at + size_t(k)] = char((v >> (8 * k)) & 0xff);
    };
    int patched = 0;
    for (size_t i = 0; i + 4 <= bytes.size(); ++i) {
        if (bytes[i] == 'P' && bytes[i + 1] == 'K' && bytes[i + 2] == 3 && bytes[i + 3] == 4) put32(i + 22, 100), ++patched;
        if (bytes[i] == 'P' && bytes[i + 1] == 'K' && bytes[i + 2] == 1 && bytes[i + 3] == 2) put32(i + 24, 100), ++patched;
    }
    ASSERT_EQ(patched, 2);
    std::ofstream(zip, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
    std::string error = unzipError(zip, t.path / "out");
    EXPECT_EQ(error.rfind(zip + ": error: entry 'zeros' ", 0), 0u) << error;
    EXPECT_NE(error.find("; nothing unpacked"), std::string::npos) << error;
}

TEST(SafeUnzip, NotAZipSaysSo) {
    testing::TestFolder t("unzip");
    std::ofstream(t.path / "x.zip") << "hello";
    std::string error;
    EXPECT_FALSE(safeUnzip((t.path / "x.zip").string(), (t.path / "out").string(), {}, error));
    EXPECT_EQ(error, (t.path / "x.zip").string() + ": error: cannot open it as a zip: Not a zip archive");
}

TEST(SafeUnzip, NamesAreCheckedAlone) {
    EXPECT_EQ(unsafeEntryName("a/b.glib"), "");
    EXPECT_EQ(unsafeEntryName("a..b/c"), "");  // '..' only as a whole component
    EXPECT_EQ(unsafeEntryName(".."), "leaves its folder (..)");
    // Backslashes are the folders older Windows tools meant (issue 29), and
    // are checked as such: a '..' or an absolute path is refused as with '/'.
    EXPECT_EQ(entryPath("week3\\shaders\\bloom.frag"), "week3/shaders/bloom.frag");
    EXPECT_EQ(unsafeEntryName(entryPath("a\\..\\b")), "leaves its folder (..)");
    EXPECT_EQ(unsafeEntryName(entryPath("..\\x")), "leaves its folder (..)");
    EXPECT_EQ(unsafeEntryName(entryPath("\\etc\\passwd")), "is an absolute path");
    EXPECT_EQ(unsafeEntryName("C:/x"), "is an absolute path (a drive letter)");
}

}  // namespace
}  // namespace glimmer
