// A fresh folder for one test, under the system's temporary folder, named
// after the process and the running test (so parallel CTest runs never
// share one), removed with everything in it when the test ends.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

namespace glimmer::testing {

struct TestFolder {
    std::filesystem::path path;
    explicit TestFolder(const std::string& stem) {
        path = std::filesystem::temp_directory_path() /
               (stem + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
        std::filesystem::create_directories(path);
    }
    ~TestFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TestFolder(const TestFolder&) = delete;
    TestFolder& operator=(const TestFolder&) = delete;
};

}  // namespace glimmer::testing
