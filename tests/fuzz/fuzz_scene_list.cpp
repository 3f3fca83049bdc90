// libFuzzer entry point: the lists of scenes `candela render @list.txt` reads (app/scene_batch.h).
// Every input is accepted or fails with UserError; what is accepted holds no blank entry, no
// comment, no list, no line break and no space at either end.
#include "scene_batch.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        const std::string_view text(reinterpret_cast<const char*>(data), size);
        for (const std::string& entry : candela::app::parseSceneList(text, "fuzz.txt")) {
            const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
            if (entry.empty() || entry[0] == '#' || entry[0] == '@' || entry.find('\n') != std::string::npos ||
                entry.find('\0') != std::string::npos || space(entry.front()) || space(entry.back())) {
                std::fprintf(stderr, "invariant violated: entry '%s'\n", entry.c_str());
                std::abort();
            }
        }
    } catch (const candela::UserError&) {
    }
    return 0;
}
