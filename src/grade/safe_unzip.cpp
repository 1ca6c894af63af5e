#include "grade/safe_unzip.h"

#include <sys/stat.h>
#include <zip.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include <fmt/format.h>

namespace glimmer {
namespace fs = std::filesystem;

std::string entryPath(const std::string& name) {
    std::string out = name;
    for (char& c : out)
        if (c == '\\') c = '/';
    return out;
}

std::string unsafeEntryName(const std::string& name) {
    if (name.empty()) return "has an empty name";
    if (name.size() > 1024) return "has a name longer than 1024 characters";
    if (name.find('\0') != std::string::npos) return "has a NUL in its name";
    if (name[0] == '/') return "is an absolute path";
    if (name.size() >= 2 && name[1] == ':') return "is an absolute path (a drive letter)";
    size_t start = 0;
    while (start <= name.size()) {
        size_t end = name.find('/', start);
        if (end == std::string::npos) end = name.size();
        if (name.compare(start, end - start, "..") == 0 && end - start == 2) return "leaves its folder (..)";
        start = end + 1;
    }
    return "";
}

namespace {

struct ZipCloser {
    void operator()(zip_t* z) const { zip_discard(z); }
};
struct FileCloser {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

bool isSymlink(zip_t* z, zip_uint64_t i) {
    zip_uint8_t opsys = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(z, i, 0, &opsys, &attributes) != 0) return false;
    return opsys == ZIP_OPSYS_UNIX && ((attributes >> 16) & S_IFMT) == S_IFLNK;
}

bool refuse(const std::string& zipPath, const std::string& destDir, const std::string& why, std::string& error) {
    error = fmt::format("{}: error: {}; nothing unpacked", zipPath, why);
    std::error_code ec;
    fs::remove_all(destDir, ec);
    return false;
}

}  // namespace

bool safeUnzip(const std::string& zipPath, const std::string& destDir, const UnzipLimits& limits, std::string& error) {
    int code = 0;
    std::unique_ptr<zip_t, ZipCloser> z(zip_open(zipPath.c_str(), ZIP_RDONLY, &code));
    if (!z) {
        zip_error_t e;
        zip_error_init_with_code(&e, code);
        error = fmt::format("{}: error: cannot open it as a zip: {}", zipPath, zip_error_strerror(&e));
        zip_error_fini(&e);
        return false;
    }
    const zip_int64_t count = zip_get_num_entries(z.get(), 0);
    if (count < 0 || zip_uint64_t(count) > limits.maxEntries)
        return refuse(zipPath, destDir,
                      fmt::format("it holds {} entries, more than the {} allowed", count, limits.maxEntries), error);
    // Everything is checked before anything is written.
    std::uint64_t total = 0;
    std::vector<std::pair<std::string, std::uint64_t>> entries;  // name, declared size
    for (zip_uint64_t i = 0; i < zip_uint64_t(count); ++i) {
        zip_stat_t st;
        zip_stat_init(&st);
        if (zip_stat_index(z.get(), i, 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
            return refuse(zipPath, destDir, fmt::format("entry {} cannot be read", i), error);
        const std::string name = entryPath(st.name);
        if (std::string why = unsafeEntryName(name); !why.empty())
            return refuse(zipPath, destDir, fmt::format("entry '{}' {}", name, why), error);
        if (isSymlink(z.get(), i))
            return refuse(zipPath, destDir, fmt::format("entry '{}' is a symbolic link", name), error);
        const std::uint64_t size = (st.valid & ZIP_STAT_SIZE) ? st.size : 0;
        if (size > limits.maxEntryBytes)
            return refuse(zipPath, destDir,
                          fmt::format("entry '{}' declares {} bytes unpacked, more than the {} allowed for one file",
                                      name, size, limits.maxEntryBytes),
                          error);
        total += size;
        if (total > limits.maxTotalBytes)
            return refuse(zipPath, destDir,
                          fmt::format("entry '{}' brings the unpacked size to {} bytes, more than the {} allowed",
                                      name, total, limits.maxTotalBytes),
                          error);
        entries.push_back({name, size});
    }
    std::error_code ec;
    fs::create_directories(destDir, ec);
    std::uint64_t written = 0;
    std::vector<char> buffer(64 * 1024);
    for (zip_uint64_t i = 0; i < entries.size(); ++i) {
        const auto& [name, declared] = entries[i];
        const fs::path target = fs::path(destDir) / name;
        if (name.back() == '/') {
            fs::create_directories(target, ec);
            continue;
        }
        fs::create_directories(target.parent_path(), ec);
        std::unique_ptr<zip_file_t, FileCloser> f(zip_fopen_index(z.get(), i, 0));
        if (!f) return refuse(zipPath, destDir, fmt::format("entry '{}' cannot be opened: {}", name, zip_strerror(z.get())), error);
        std::ofstream out(target, std::ios::binary | std::ios::trunc);
        if (!out) return refuse(zipPath, destDir, fmt::format("entry '{}' cannot be written", name), error);
        std::uint64_t got = 0;
        for (;;) {
            // Never more than one byte past what the entry declared: that byte proves the lie.
            const zip_uint64_t want = std::min<std::uint64_t>(buffer.size(), declared + 1 - got);
            const zip_int64_t n = zip_fread(f.get(), buffer.data(), want);
            if (n < 0)
                return refuse(zipPath, destDir,
                              fmt::format("entry '{}' cannot be unpacked: {}", name, zip_file_strerror(f.get())), error);
            if (n == 0) break;
            got += std::uint64_t(n);
            written += std::uint64_t(n);
            if (got > declared)
                return refuse(zipPath, destDir,
                              fmt::format("entry '{}' unpacks to more than the {} bytes it declares", name, declared),
                              error);
            if (written > limits.maxTotalBytes)
                return refuse(zipPath, destDir, fmt::format("entry '{}' brings the unpacked size over the {} bytes allowed",
                                                            name, limits.maxTotalBytes),
                              error);
            out.write(buffer.data(), n);
        }
        if (!out) return refuse(zipPath, destDir, fmt::format("entry '{}' cannot be written", name), error);
    }
    return true;
}

}  // namespace glimmer
