#include "core/log.h"

#include <atomic>
#include <cstdio>

namespace candela::log {
namespace {
std::atomic<bool> gVerbose{false};
thread_local Capture* tCapture = nullptr;

void print(const char* prefix, std::string_view message) {
    std::fprintf(stderr, "%s%.*s\n", prefix, static_cast<int>(message.size()), message.data());
}
}  // namespace

void setVerbose(bool value) { gVerbose = value; }
bool verbose() { return gVerbose; }
void info(std::string_view message) {
    if (tCapture) tCapture->infos.emplace_back(message);
    if (gVerbose) print("candela: ", message);
}
void warn(std::string_view message) {
    if (tCapture) tCapture->warnings.emplace_back(message);
    print("candela: warning: ", message);
}

Capture::Capture() : mOuter(tCapture) { tCapture = this; }
Capture::~Capture() { tCapture = mOuter; }
void error(std::string_view message) { print("candela: error: ", message); }

}  // namespace candela::log
