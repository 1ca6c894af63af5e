#include "plan/sandbox.h"

#include <cstdint>
#include <filesystem>

#include <fmt/format.h>
#include <sys/stat.h>

namespace fs = std::filesystem;

namespace glimmer {
namespace {

bool inside(const fs::path& p, const fs::path& root) {
    auto r = root.begin(), q = p.begin();
    for (; r != root.end(); ++r, ++q)
        if (q == p.end() || *q != *r) return false;
    return q != p.end();  // strictly below the root
}

// Where `p` leads: its symlinks followed by reading them, dangling or not
// (a dangling link out must read as "outside", as a live one does, or the
// message would tell whether its target exists), then the folders above
// resolved as far as they exist.
fs::path leadsTo(fs::path p, std::error_code& ec) {
    for (int hop = 0; hop < 40; ++hop) {  // the kernel's own bound on a chain of links
        if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
        fs::path target = fs::read_symlink(p, ec);
        if (ec) return {};
        p = target.is_absolute() ? target : p.parent_path() / target;
    }
    ec.clear();
    return fs::weakly_canonical(p, ec);
}

}  // namespace

SandboxLookup resolveSandboxed(const std::string& scriptFile, const std::string& name,
                               const std::vector<std::string>& includeDirs, std::string& path,
                               std::vector<std::string>& tried, std::string& why) {
    std::vector<fs::path> roots;
    std::error_code ec;
    fs::path scriptDir = fs::path(scriptFile).parent_path();
    std::vector<fs::path> given = {scriptDir.empty() ? fs::path(".") : scriptDir};
    for (const auto& d : includeDirs) given.emplace_back(d);
    for (const auto& g : given) {
        tried.push_back(g.lexically_normal().string());
        fs::path real = fs::canonical(g, ec);
        if (!ec && fs::is_directory(real, ec)) roots.push_back(real);
    }
    if (fs::path(name).is_absolute()) {
        why = "an absolute path";
        return SandboxLookup::Outside;
    }
    for (const auto& root : roots) {
        fs::path candidate = root / name;
        // Where the name leads, worked out without asking whether the file
        // there exists: a student must not learn from the message whether a
        // file outside the sandbox exists, nor where a link points (issue 30).
        fs::path real = leadsTo(candidate, ec);
        if (ec) continue;
        bool in = false;
        for (const auto& r : roots) in |= inside(real, r);
        if (!in) {
            why = "it leads outside the script's folder";
            return SandboxLookup::Outside;
        }
        struct stat st{};
        if (::stat(real.c_str(), &st) != 0) continue;  // not there (or a dangling link): look on
        if (!S_ISREG(st.st_mode)) {
            why = "not a regular file";
            return SandboxLookup::Outside;
        }
        // A hard link is the same file under two names, and the other name
        // may be anywhere on the disk: nothing here can tell where.
        if (st.st_nlink > 1) {
            why = fmt::format("a file with {} hard links (another name may be outside the script's folder)",
                              std::uint64_t(st.st_nlink));
            return SandboxLookup::Outside;
        }
        path = real.string();
        return SandboxLookup::Found;
    }
    return SandboxLookup::NotFound;
}

}  // namespace glimmer
