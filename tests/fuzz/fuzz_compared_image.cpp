// libFuzzer entry point: the images `candela diff` compares (reports/compared_image.h). The first
// byte chooses the format (even: PNG, odd: EXR); the rest is the file, written to a temporary file
// of that extension (the reader takes paths). Every input is read or fails with UserError; what is
// read has the size it says, and linear values that are finite and ≥ 0.
#include "core/errors.h"
#include "reports/compared_image.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

[[noreturn]] void violated(const std::string& what) {
    std::fprintf(stderr, "invariant violated: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const bool exr = data[0] & 1;
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("candela_fuzz_compared_" + std::to_string(::getpid()) + (exr ? ".exr" : ".png"));
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    try {
        const candela::reports::ComparedImage image = candela::reports::readComparedImage(file);
        const size_t values = size_t(image.width) * image.height * 3;
        if (image.width == 0 || image.height == 0) violated("an empty image was read");
        if (image.linear.width != image.width || image.linear.height != image.height || image.linear.rgb.size() != values)
            violated("linear size");
        if (!exr && image.rgb8.size() != values) violated("8-bit size");
        for (float v : image.linear.rgb)
            if (!std::isfinite(v) || v < 0.0f) violated("a linear value not finite or negative");
    } catch (const candela::UserError&) {
    }
    std::filesystem::remove(file);
    return 0;
}
