#include <filesystem>

#include "plan/plan.h"

namespace fs = std::filesystem;

namespace glimmer {

std::string resolveFile(const std::string& scriptFile, const std::string& name,
                        const std::vector<std::string>& includeDirs, std::vector<std::string>* tried) {
    fs::path p(name);
    if (p.is_absolute()) {
        if (tried) tried->push_back(p.parent_path().string());
        return fs::is_regular_file(p) ? p.string() : std::string();
    }
    fs::path scriptDir = fs::path(scriptFile).parent_path();
    // The seed scripts name "superblur.vert" and "grid.bmp" bare; the project
    // keeps shaders and textures in folders of their own beside scripts/.
    std::vector<fs::path> dirs = {scriptDir, scriptDir / ".." / "shaders", scriptDir / ".." / "textures"};
    for (const auto& d : includeDirs) dirs.emplace_back(d);
    for (const auto& d : dirs) {
        fs::path candidate = d / p;
        if (tried) tried->push_back(d.empty() ? std::string(".") : d.lexically_normal().string());
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
    }
    return {};
}

std::string sameNameButCase(const std::vector<std::string>& folders, const std::string& name) {
    fs::path p(name);
    if (p.is_absolute() || name.find("..") != std::string::npos || !p.has_filename()) return {};
    auto lower = [](std::string t) {
        for (char& c : t)
            if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        return t;
    };
    const std::string want = lower(p.filename().string());
    for (const auto& folder : folders) {
        std::error_code ec;
        const fs::path dir = fs::path(folder) / p.parent_path();
        int looked = 0;  // a folder of a million files is not read whole for a hint
        for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator() && ++looked <= 2000;
             it.increment(ec)) {
            const std::string have = it->path().filename().string();
            if (have != p.filename().string() && lower(have) == want && it->is_regular_file(ec))
                return (p.parent_path() / have).string();
        }
    }
    return {};
}

}  // namespace glimmer
