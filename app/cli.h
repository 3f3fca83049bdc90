#pragma once
// Command-line parsing for the `candela` executable. Pure (no Vulkan), unit-tested.
// Every malformed argument throws candela::UserError with a one-line message naming the flag.

#include <optional>
#include <string>
#include <vector>

namespace candela::app {

struct CommonOptions {
    std::string device;     // --device INDEX|NAME
    bool validate = false;  // --validate
    bool verbose = false;   // --verbose
};

struct RenderOptions {
    CommonOptions common;
    std::string out = "candela.png";  // --out FILE (.png, .exr, .pfm)
    uint32_t width = 1280;            // --width W
    uint32_t height = 720;            // --height H
    std::string graphDot;             // --graph-dot FILE
    std::string graphJson;            // --graph-json FILE
    std::vector<std::string> disabledPasses;  // --disable-pass NAME (repeatable)
};

struct InfoOptions {
    CommonOptions common;
};

struct Command {
    enum class Kind { Help, Render, Info } kind = Kind::Help;
    RenderOptions render;
    InfoOptions info;
};

// Parses argv[1..]. No arguments or --help → Kind::Help.
Command parseCommandLine(const std::vector<std::string>& args);

// Usage text printed by `candela --help`.
std::string usageText();

// Parses a decimal integer in [0, 2^32): "--width" and "abc" → UserError naming the flag.
uint32_t parseDimension(const std::string& flag, const std::string& value);

}  // namespace candela::app
