#pragma once
// The scenes of one `candela render` run and the names of what it writes. Pure (files are listed,
// not read as glTF), unit-tested.
//
// A run's inputs are glTF files, folders (walked for .gltf and .glb files, in sorted order) and
// list files (`@list.txt`: one file or folder per line, relative to the working folder; blank lines
// and lines starting with # are skipped). The scenes keep the order of the inputs; a file reached
// twice is rendered once.

#include "core/errors.h"

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela::app {

struct SceneInput {
    std::filesystem::path file;  // as given, or found under a given folder
    std::string name;            // {name}: the file's name without extension ("Box")
    // {path}: the file's path without extension, relative to the folder it was found under
    // ("Box/glTF-Binary/Box"), or as given for a file named directly (leading "/", "./" and ".."
    // components dropped, so that it stays inside the output folder).
    std::string path;
    bool operator==(const SceneInput&) const = default;
};

// The entries of a list of scenes (`@list.txt`) with contents `text`: one per line, spaces around
// it trimmed, blank lines and lines starting with # skipped (a \r before the newline is a space).
// Throws UserError naming `list` for an entry that names another list (@…) or a NUL byte.
std::vector<std::string> parseSceneList(std::string_view text, const std::string& list);

// The scene of the file `file` (--scene: never walked as a folder).
SceneInput fileInput(const std::filesystem::path& file);

// The scenes `inputs` name, in order. A path that does not exist is kept as a scene (its load
// fails and is reported with the others); a folder holding no glTF file adds nothing. Throws
// UserError for an unreadable list file, a list inside a list, or when no scene is found at all.
std::vector<SceneInput> expandSceneInputs(const std::vector<std::string>& inputs);

// --shard I/N: the scenes at positions k (from 0) with k mod N = I − 1. Shards 1 … N of the same
// list are disjoint and together hold every scene.
struct Shard {
    uint32_t index = 1;  // 1 … count
    uint32_t count = 1;
    bool operator==(const Shard&) const = default;
};
// Reads an environment variable (null: unset); std::getenv by default, a table in tests.
using EnvironmentLookup = std::function<const char*(const char* name)>;
// Parses "I/N" (1 ≤ I ≤ N), or "auto" / "auto/N": the index from a job array's environment —
// Slurm's SLURM_ARRAY_TASK_ID (less SLURM_ARRAY_TASK_MIN, with SLURM_ARRAY_TASK_COUNT shards), a
// Kubernetes indexed job's JOB_COMPLETION_INDEX (from 0; N must be given), GitLab's CI_NODE_INDEX
// (from 1, CI_NODE_TOTAL shards) — N, when given, taking precedence over the count found.
// UserError naming `flag` otherwise.
Shard parseShard(const std::string& flag, const std::string& value, const EnvironmentLookup& env = [](const char* name) {
    return static_cast<const char*>(std::getenv(name));
});
std::vector<SceneInput> shardOf(const std::vector<SceneInput>& scenes, Shard shard);

// What the fields of an --out pattern stand for in one output file.
struct OutputFields {
    std::string name;               // {name}
    std::string path;               // {path}
    std::string variant;            // {variant}: the KHR_materials_variants variant, or "default"
    std::optional<uint32_t> frame;  // {frame}: frame of an image sequence (4 digits at least)
};
// Throws UserError when `pattern` has a {field} other than name, path, variant and frame.
void checkOutPattern(const std::string& pattern);
// Whether `pattern` uses {field} ("name", "path", "variant" or "frame").
bool usesField(const std::string& pattern, const std::string& field);
// `pattern` with its fields replaced. A frame of a pattern without {frame} goes into its one %d
// or %0Nd (sequenceFileName). Precondition: checkOutPattern(pattern) passed.
std::string expandOutPattern(const std::string& pattern, const OutputFields& fields);

}  // namespace candela::app
