#pragma once
// Errors that need no Vulkan: the user's bad input (UserError) and a broken contract between
// Candela's own parts (InternalError), and formatBytes and formatNumber for their messages.
// Included by every CPU library (the file readers among them), so it must never include a Vulkan
// header; the Vulkan errors and VK_CHECK are vk/check.h.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace candela {

// "144 B", "12.0 KiB", "12.5 MiB", "1.5 GiB"
std::string formatBytes(uint64_t bytes);
// `value` printed by the printf pattern `pattern`, which takes one double ("%.2f s"); at most 63
// characters are kept.
std::string formatNumber(const char* pattern, double value);

// An error caused by the user's input (flags, files): the message is one line naming the
// problem (and the file, if any). Front ends print it and exit non-zero.
class UserError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Candela broke a contract between two of its own parts — a pass naming a descriptor binding its
// shader does not declare, push constants of the wrong size, an object placed in memory too small
// for it. A bug, never the user's input: front ends report it as an internal error.
class InternalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace candela
