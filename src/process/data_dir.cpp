#include "process/data_dir.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace glimmer {

std::string dataDir() {
    namespace fs = std::filesystem;
    auto holdsData = [](const fs::path& p) {
        std::error_code ec;
        return fs::is_directory(p / "scripts" / "bloom", ec);
    };
    if (const char* env = std::getenv("GLIMMER_DATA_DIR"); env && *env && holdsData(env)) return env;
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path installed = exe.parent_path().parent_path() / "share" / "glimmer";
        if (holdsData(installed)) return installed.string();
    }
    return GLIMMER_SOURCE_DIR;
}

}  // namespace glimmer
