#include "core/errors.h"

#include <cstdio>

namespace candela {

std::string formatBytes(uint64_t bytes) {
    char text[32];
    if (bytes < 1024)
        std::snprintf(text, sizeof(text), "%llu B", static_cast<unsigned long long>(bytes));
    else if (bytes < (1u << 20))
        std::snprintf(text, sizeof(text), "%.1f KiB", double(bytes) / 1024.0);
    else if (bytes < (1ull << 30))
        std::snprintf(text, sizeof(text), "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    else
        std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / (1024.0 * 1024.0 * 1024.0));
    return text;
}

std::string formatNumber(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace candela
