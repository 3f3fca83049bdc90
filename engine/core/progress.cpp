#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace candela {

Progress::Progress(std::string task, size_t total, bool quiet, std::FILE* out, std::optional<bool> terminal, double interval)
    : mTask(std::move(task)),
      mTotal(std::max<size_t>(total, 1)),
      mQuiet(quiet),
      mOut(out),
      mTerminal(terminal.value_or(out && isatty(fileno(out)) != 0)),
      mInterval(interval),
      mStart(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

double Progress::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
}

std::string Progress::formatDuration(double seconds) {
    const long total = std::lround(std::max(seconds, 0.0));
    char text[32];
    if (total >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}

std::string Progress::line(size_t done, const std::string& detail, double seconds) const {
    std::string out = mTask + ": " + std::to_string(done) + "/" + std::to_string(mTotal) + "  " + formatDuration(seconds) +
                      " elapsed";
    if (done > 0 && done < mTotal) out += ", ~" + formatDuration(seconds / double(done) * double(mTotal - done)) + " left";
    if (!detail.empty()) out += "  " + detail;
    return out;
}

void Progress::step(size_t done, const std::string& detail) {
    if (mQuiet || !mOut) return;
    const double now = elapsed();
    const std::string text = line(done, detail, now);
    if (mTerminal) {
        // Carriage return, the line, and blanks over whatever the previous one left.
        std::fprintf(mOut, "\r%s%*s", text.c_str(), int(mLastLength > text.size() ? mLastLength - text.size() : 0), "");
        mLastLength = text.size();
        mOpen = true;
    } else if (!mLastPrinted || now - *mLastPrinted >= mInterval || done >= mTotal) {
        std::fprintf(mOut, "%s\n", text.c_str());
        mLastPrinted = now;
    }
    std::fflush(mOut);
}

void Progress::clear() {
    if (!mOpen) return;
    std::fprintf(mOut, "\r%*s\r", int(mLastLength), "");
    std::fflush(mOut);
    mLastLength = 0;
    mOpen = false;
}

void Progress::finish() {
    if (mOpen) std::fprintf(mOut, "\n");
    mOpen = false;
}

}  // namespace candela
