#pragma once
// Comparing image files for `candela diff`: one pair (both PNG: LDR-ꟻLIP on the decoded display
// values; both EXR: HDR-ꟻLIP on the radiance), or two folders matched by relative path.

#include "reports/diff_results.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace candela::reports {

// Compares `reference` with `test` and fills a DiffPair named `name`: the ꟻLIP statistics, the
// pixel differences and the status under the settings' thresholds. A file that cannot be read
// gives status Unreadable and a size difference SizeMismatch (with the reader's or a one-line
// message), not an exception. With `errorMap`, the ꟻLIP value of each pixel is stored there
// (width × height, top row first; emptied when nothing was compared).
// Throws UserError when the files are of different formats (a PNG against an EXR) or either
// extension is neither .png nor .exr.
DiffPair diffImages(const std::filesystem::path& reference, const std::filesystem::path& test, const std::string& name,
                    const DiffSettings& settings, std::vector<float>* errorMap = nullptr);

// The .png and .exr files under two folders (recursively, extensions in any case), matched by
// their path relative to each folder, sorted by it; each side is nullopt where the file is missing.
// Directories and other files are skipped. Throws UserError naming a folder that cannot be read.
struct MatchedFile {
    std::string name;  // relative path with '/' separators
    std::optional<std::filesystem::path> reference, test;
};
std::vector<MatchedFile> matchFolders(const std::filesystem::path& reference, const std::filesystem::path& test);

}  // namespace candela::reports
