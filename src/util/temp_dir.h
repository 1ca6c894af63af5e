// A folder of one's own under the system's temporary folder, removed with
// everything in it when the owner goes out of scope, on every return path.
#pragma once
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

namespace glimmer {

class TempDir {
public:
    // `stem` names the owner ("glimmer-tradeoff"); the process id keeps two
    // runs apart.
    explicit TempDir(const std::string& stem)
        : path_(std::filesystem::temp_directory_path() / (stem + "-" + std::to_string(::getpid()))) {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
        std::filesystem::create_directories(path_, ec);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace glimmer
