#include "core/cache_files.h"

#include "core/errors.h"

#include <algorithm>
#include <atomic>
#include <bit>
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

fs::path lodCacheFolder(const std::string& choice) {
    if (choice == "off") return {};
    if (!choice.empty()) return fs::path(choice);
    const fs::path user = userCacheFolder();
    return user.empty() ? fs::path() : user / "lod";
}

namespace {

// One word into the state: xor in, multiply by a large odd constant (every input bit reaches the
// high half), fold the high half down (and so into the next multiply's low bits).
uint64_t mixWord(uint64_t h, uint64_t word) {
    h = (h ^ word) * 0x9e3779b97f4a7c15ull;
    return h ^ (h >> 32);
}

// The 8 bytes at `p` as a little-endian word, on any host.
uint64_t loadLe64(const unsigned char* p) {
    uint64_t word;
    std::memcpy(&word, p, sizeof word);
    if constexpr (std::endian::native == std::endian::big) word = __builtin_bswap64(word);
    return word;
}

}  // namespace

void WordHasher::update(const void* bytes, size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    mSize += size;
    size_t i = 0;
    for (; mPendingBytes != 0 && i < size; ++i) {  // complete the word begun
        mPending |= uint64_t(p[i]) << (8 * mPendingBytes);
        if (++mPendingBytes == 8) {
            mHash = mixWord(mHash, mPending);
            mPending = 0;
            mPendingBytes = 0;
        }
    }
    for (; i + 8 <= size; i += 8) mHash = mixWord(mHash, loadLe64(p + i));
    for (; i < size; ++i, ++mPendingBytes) mPending |= uint64_t(p[i]) << (8 * mPendingBytes);
}

uint64_t WordHasher::value() const { return mixWord(mixWord(mHash, mPending), mSize); }

uint64_t wordHash64(uint64_t hash, const void* bytes, size_t size) {
    WordHasher hasher(hash);
    hasher.update(bytes, size);
    return hasher.value();
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

void touchCacheFile(const fs::path& path) {
    std::error_code ec;
    fs::last_write_time(path, fs::file_time_type::clock::now(), ec);
}

std::vector<fs::path> evictCacheFiles(const fs::path& dir, std::string_view extension, uint64_t capBytes,
                                      const fs::path& keep) {
    struct Entry {
        fs::path path;
        fs::file_time_type used;
        uint64_t bytes;
    };
    std::vector<Entry> entries;
    uint64_t total = 0;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code fileError;
        if (it->path().extension() != extension || !it->is_regular_file(fileError)) continue;
        const uint64_t bytes = it->file_size(fileError);
        const fs::file_time_type used = fs::last_write_time(it->path(), fileError);
        if (fileError) continue;
        total += bytes;
        if (it->path() != keep) entries.push_back({it->path(), used, bytes});
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
    std::vector<fs::path> removed;
    for (const Entry& entry : entries) {
        if (total <= capBytes) break;
        std::error_code removeError;
        if (fs::remove(entry.path, removeError) && !removeError) removed.push_back(entry.path);
        total -= entry.bytes;  // removed, or gone already (another process evicted it)
    }
    return removed;
}

}  // namespace candela
