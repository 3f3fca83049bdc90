#pragma once
// Minimal leveled logging to stderr. Warnings and errors always print; info only when verbose.

#include <string_view>

namespace candela::log {

void setVerbose(bool verbose);
bool verbose();
void info(std::string_view message);
void warn(std::string_view message);
void error(std::string_view message);

}  // namespace candela::log
