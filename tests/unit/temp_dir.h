#pragma once
// A fresh folder under the system temp directory (unique per process and instance), removed with
// everything in it on destruction. Shared by the unit tests that write files.

#include <atomic>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace candela::test {

class TempDir {
public:
    explicit TempDir(const std::string& prefix = "candela_test") {
        static std::atomic<int> counter{0};
        mPath = std::filesystem::temp_directory_path() /
                (prefix + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::remove_all(mPath);
        std::filesystem::create_directories(mPath);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(const std::string& name) const { return mPath / name; }

private:
    std::filesystem::path mPath;
};

}  // namespace candela::test
