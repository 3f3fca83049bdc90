#pragma once
// Progress of a long command (ibl-report, soak, image sequences, scale-report, quality-report) on
// stderr. On a terminal: one line that rewrites itself ("ibl-report: 12/40  0:42 elapsed, ~1:58
// left  prefilter 64 samples"). Elsewhere (CI logs, pipes): the same as plain lines, the first step,
// then at most one every `interval` seconds, and the last. Quiet: nothing.

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace candela {

class Progress {
public:
    // `task` prefixes every line; `total` steps are expected (≥ 1). `terminal`: nullopt asks
    // isatty() of `out`. Borrows `out`.
    Progress(std::string task, size_t total, bool quiet = false, std::FILE* out = stderr,
             std::optional<bool> terminal = std::nullopt, double interval = 10.0);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // `done` of the total steps are complete; `detail` says what the last one was.
    void step(size_t done, const std::string& detail = {});
    // Ends the self-updating line (a newline on a terminal). Called by the destructor if needed.
    void finish();
    // Blanks the self-updating line, so that other output can follow (the next step redraws it).
    void clear();

    // "0:42", "12:05", "1:02:03".
    static std::string formatDuration(double seconds);
    // The line step() prints, at `elapsed` seconds (for tests).
    std::string line(size_t done, const std::string& detail, double elapsed) const;

private:
    double elapsed() const;

    std::string mTask;
    size_t mTotal;
    bool mQuiet;
    std::FILE* mOut;
    bool mTerminal;
    double mInterval;
    std::chrono::steady_clock::time_point mStart;
    std::optional<double> mLastPrinted;  // elapsed seconds at the last plain line
    size_t mLastLength = 0;              // of the terminal line, to blank what a shorter one leaves
    bool mOpen = false;                  // a terminal line without its newline yet
};

}  // namespace candela
