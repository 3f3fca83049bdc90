// Progress: one self-updating line on a terminal, plain rate-limited lines elsewhere, nothing when
// quiet; the text shows step, count, elapsed and estimated remaining time.

#include "core/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace candela {
namespace {

// Everything written to `file` so far.
std::string contents(std::FILE* file) {
    std::fflush(file);
    std::rewind(file);
    std::string out;
    for (int c; (c = std::fgetc(file)) != EOF;) out += char(c);
    return out;
}

TEST(Progress, LineShowsStepCountElapsedAndRemaining) {
    const Progress progress("ibl-report", 40, true);
    EXPECT_EQ(progress.line(10, "prefilter 64 samples", 30.0), "ibl-report: 10/40  0:30 elapsed, ~1:30 left  prefilter 64 samples");
    EXPECT_EQ(progress.line(40, "", 3725.0), "ibl-report: 40/40  1:02:05 elapsed");
    EXPECT_EQ(Progress::formatDuration(59.6), "1:00");
}

TEST(Progress, OnATerminalOneLineRewritesItself) {
    std::FILE* file = std::tmpfile();
    {
        Progress progress("soak", 3, false, file, true);
        progress.step(1, "a longer detail");
        progress.step(2, "b");
    }
    const std::string text = contents(file);
    std::fclose(file);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;  // the newline at the end only
    EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 2) << text;
    EXPECT_NE(text.find("soak: 2/3"), std::string::npos) << text;
}

TEST(Progress, ElsewherePlainLinesAtMostEveryIntervalAndTheLast) {
    std::FILE* file = std::tmpfile();
    {
        Progress progress("render", 100, false, file, false, 3600.0);
        for (size_t i = 1; i <= 100; ++i) progress.step(i);
    }
    const std::string text = contents(file);
    std::fclose(file);
    EXPECT_EQ(text.find('\r'), std::string::npos);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;  // the first step and the last
    EXPECT_NE(text.find("render: 1/100"), std::string::npos);
    EXPECT_NE(text.find("render: 100/100"), std::string::npos);
}

TEST(Progress, QuietPrintsNothing) {
    std::FILE* file = std::tmpfile();
    {
        Progress progress("render", 2, true, file, true);
        progress.step(1);
        progress.step(2);
    }
    EXPECT_EQ(contents(file), "");
    std::fclose(file);
}

}  // namespace
}  // namespace candela
