#include "core/cache_files.h"

#include "core/errors.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>

namespace candela {
namespace {

namespace fs = std::filesystem;

// 64 bits for a temporary file name unique among concurrent writers (processes and threads).
uint64_t randomTag() {
    static std::atomic<uint64_t> counter{0};
    uint64_t tag = uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()) ^ (counter++ * kFnv1a64Prime);
    try {
        std::random_device device;
        tag ^= uint64_t(device()) << 32 | device();
    } catch (const std::exception&) {
        // No entropy source: the clock and counter alone.
    }
    return tag;
}

// Removes the file at `path` on destruction unless released.
struct TemporaryFile {
    fs::path path;
    bool keep = false;
    ~TemporaryFile() {
        std::error_code ec;
        if (!keep) fs::remove(path, ec);
    }
};

}  // namespace

fs::path userCacheFolder(const char* xdgCacheHome, const char* home) {
    // The specification: a relative XDG_CACHE_HOME is invalid and is ignored.
    if (xdgCacheHome && *xdgCacheHome && fs::path(xdgCacheHome).is_absolute()) return fs::path(xdgCacheHome) / "candela";
    if (home && *home) return fs::path(home) / ".cache" / "candela";
    return {};
}

fs::path userCacheFolder() { return userCacheFolder(std::getenv("XDG_CACHE_HOME"), std::getenv("HOME")); }

fs::path pipelineCacheFolder(const std::string& choice) {
    if (choice == "off") return {};
    return choice.empty() ? userCacheFolder() : fs::path(choice);
}

fs::path iblCacheFolder(const std::string& choice) {
    if (choice == "off") return {};
    if (!choice.empty()) return fs::path(choice);
    const fs::path user = userCacheFolder();
    return user.empty() ? fs::path() : user / "ibl";
}

std::string hex16(uint64_t v) {
    std::string s(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4) s[size_t(i)] = "0123456789abcdef"[v & 0xf];
    return s;
}

void writeFileAtomically(const fs::path& path, const std::function<void(std::ostream& out)>& write) {
    const std::string name = path.string();
    std::error_code ec;
    if (const fs::path dir = path.parent_path(); !dir.empty()) {
        fs::create_directories(dir, ec);
        if (ec) throw UserError(name + ": cannot create the directory '" + dir.string() + "': " + ec.message());
    }
    TemporaryFile temporary{path.parent_path() / (path.filename().string() + ".tmp-" + hex16(randomTag()))};
    {
        std::ofstream out(temporary.path, std::ios::binary | std::ios::trunc);
        if (!out)
            throw UserError(name + ": cannot create the temporary file '" + temporary.path.string() + "': " + std::strerror(errno));
        write(out);
        out.flush();
        if (!out) throw UserError(name + ": write failed: " + std::strerror(errno));
        out.close();
        if (!out) throw UserError(name + ": write failed on close: " + std::strerror(errno));
    }
    fs::rename(temporary.path, path, ec);
    if (ec) throw UserError(name + ": cannot rename the temporary file '" + temporary.path.string() + "' to it: " + ec.message());
    temporary.keep = true;
}

}  // namespace candela
