#include "plan/sandbox.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace glimmer {
namespace {

bool inside(const fs::path& p, const fs::path& root) {
    auto r = root.begin(), q = p.begin();
    for (; r != root.end(); ++r, ++q)
        if (q == p.end() || *q != *r) return false;
    return q != p.end();  // strictly below the root
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
        if (!fs::exists(fs::symlink_status(candidate, ec))) continue;
        fs::path real = fs::canonical(candidate, ec);  // every symlink followed
        if (ec) continue;                              // a dangling link: not there
        bool in = false;
        for (const auto& r : roots) in |= inside(real, r);
        if (!in) {
            why = "it leads to " + real.string();
            return SandboxLookup::Outside;
        }
        if (!fs::is_regular_file(real, ec)) {
            why = "not a regular file";
            return SandboxLookup::Outside;
        }
        path = real.string();
        return SandboxLookup::Found;
    }
    return SandboxLookup::NotFound;
}

}  // namespace glimmer
