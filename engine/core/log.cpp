#include "core/log.h"

#include <atomic>
#include <cstdio>

namespace candela::log {
namespace {
std::atomic<bool> gVerbose{false};

void print(const char* prefix, std::string_view message) {
    std::fprintf(stderr, "%s%.*s\n", prefix, static_cast<int>(message.size()), message.data());
}
}  // namespace

void setVerbose(bool value) { gVerbose = value; }
bool verbose() { return gVerbose; }
void info(std::string_view message) {
    if (gVerbose) print("candela: ", message);
}
void warn(std::string_view message) { print("candela: warning: ", message); }
void error(std::string_view message) { print("candela: error: ", message); }

}  // namespace candela::log
