#pragma once
// What `candela diff` found, as plain data: one DiffPair per image pair, with the settings they
// were compared under. The command prints and writes JSON from it (app/diff_command.cpp); a page
// generator can take the same struct. Definitions of the numbers: docs/pipelines.md#candela-diff.

#include "reports/flip.h"
#include "reports/pixel_difference.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace candela::reports {

enum class DiffStatus {
    Ok,             // compared, and within every threshold given
    OverThreshold,  // compared: mean ꟻLIP above --max-flip or the fraction above --max-fraction
    Missing,        // the image is on one side only
    SizeMismatch,   // the two images differ in width or height
    Unreadable,     // a file could not be read (message: the reader's one-line error)
};

// Each status as printed ("size mismatch") and as a JSON key or value ("sizeMismatch").
struct DiffStatusName {
    DiffStatus status;
    const char* text;
    const char* key;
};
inline constexpr DiffStatusName kDiffStatusNames[] = {{DiffStatus::Ok, "ok", "ok"},
                                                     {DiffStatus::OverThreshold, "over threshold", "overThreshold"},
                                                     {DiffStatus::Missing, "missing", "missing"},
                                                     {DiffStatus::SizeMismatch, "size mismatch", "sizeMismatch"},
                                                     {DiffStatus::Unreadable, "unreadable", "unreadable"}};

inline const DiffStatusName& diffStatusName(DiffStatus status) {
    for (const DiffStatusName& name : kDiffStatusNames)
        if (name.status == status) return name;
    return kDiffStatusNames[0];
}

struct DiffSettings {
    float pixelsPerDegree = 0.0f;  // what ꟻLIP was computed at
    ViewingConditions viewing;     // the monitor it came from, unless ppdGiven
    bool ppdGiven = false;         // --ppd set it directly
    // A pixel is "over" when one of its channels differs by more than this many levels of 255
    // (EXR: this / 255 in linear units).
    double thresholdLevels = 5.0;
    std::optional<double> maxFlip;      // a pair fails when its mean ꟻLIP is above
    std::optional<double> maxFraction;  // a pair fails when its fraction of pixels over is above
};

struct DiffPair {
    std::string name;           // the path relative to the compared folders (two files: the test's file name)
    std::string referencePath;  // "" when missing
    std::string testPath;       // "" when missing
    std::string errorMapPath;   // the magma PNG written ("" none)
    DiffStatus status = DiffStatus::Ok;
    std::string message;        // why it is not ok, one line ("" when ok)
    std::vector<std::string> warnings;  // the readers' warnings ("PATH: ..."), e.g. NaN values replaced
    bool hdr = false;           // EXR pair: HDR-ꟻLIP; differences in linear units
    uint32_t width = 0, height = 0;  // of the reference, when it was read
    // Set for compared pairs (Ok, OverThreshold):
    FlipStatistics flip;
    std::optional<FlipExposures> exposures;  // HDR only
    PixelDifference pixels;     // maxChannelDifference in levels (PNG) or linear units (EXR)

    bool compared() const { return status == DiffStatus::Ok || status == DiffStatus::OverThreshold; }
};

struct DiffReport {
    DiffSettings settings;
    std::vector<DiffPair> pairs;

    size_t count(DiffStatus status) const {
        size_t n = 0;
        for (const DiffPair& pair : pairs) n += pair.status == status;
        return n;
    }
    bool passed() const { return count(DiffStatus::Ok) == pairs.size(); }
};

}  // namespace candela::reports
