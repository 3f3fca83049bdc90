#pragma once
// Minimal leveled logging to stderr. Warnings and errors always print; info only when verbose.

#include <string>
#include <string_view>
#include <vector>

namespace candela::log {

void setVerbose(bool verbose);
bool verbose();
void info(std::string_view message);
void warn(std::string_view message);
void error(std::string_view message);

// While alive, also keeps the warnings (and, verbose or not, the infos) this thread logs, for a
// report of what happened during one piece of work (`candela render`'s report per scene). They
// are printed as before. Captures nest: the innermost one keeps the lines.
class Capture {
public:
    Capture();
    ~Capture();
    Capture(const Capture&) = delete;
    Capture& operator=(const Capture&) = delete;

    std::vector<std::string> warnings;
    std::vector<std::string> infos;

private:
    Capture* mOuter;
};

}  // namespace candela::log
