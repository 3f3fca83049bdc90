#include "scene_batch.h"

#include "cli_values.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <set>

namespace candela::app {
namespace {

namespace fs = std::filesystem;

bool isGltf(const fs::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".gltf" || extension == ".glb";
}

// `path` without its extension, as a relative path with only named components ("a/b/Box").
std::string relativeStem(const fs::path& path) {
    fs::path out;
    for (const fs::path& part : path.parent_path())
        if (part != "/" && part != "." && part != ".." && !part.has_root_name() && !part.empty()) out /= part;
    out /= path.stem();
    return out.generic_string();
}

class Collector {
public:
    void add(const fs::path& file, std::string path) {
        std::error_code ec;
        const fs::path key = fs::weakly_canonical(file, ec);
        if (!mSeen.insert(ec ? file.lexically_normal().string() : key.string()).second) return;
        SceneInput scene = fileInput(file);
        scene.path = std::move(path);
        mScenes.push_back(std::move(scene));
    }

    // A file, or a folder walked for glTF files; `listed`: named by a list file (no lists inside).
    void input(const std::string& input, bool listed) {
        if (!listed && input.size() > 1 && input[0] == '@') return list(input.substr(1));
        std::error_code ec;
        if (!fs::is_directory(input, ec)) return add(input, relativeStem(input));
        std::vector<fs::path> files;
        const auto options = fs::directory_options::skip_permission_denied;
        for (fs::recursive_directory_iterator it(input, options, ec), end; !ec && it != end; it.increment(ec))
            if (it->is_regular_file(ec) && isGltf(it->path())) files.push_back(it->path());
        if (ec) throw UserError(input + ": cannot list the folder: " + ec.message());
        std::sort(files.begin(), files.end());
        for (const fs::path& file : files) add(file, relativeStem(file.lexically_relative(input)));
    }

    void list(const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        if (!in) throw UserError("@" + file + ": cannot open the list of scenes");
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        if (in.bad()) throw UserError("@" + file + ": cannot read the list of scenes");
        for (const std::string& entry : parseSceneList(text, file)) input(entry, true);
    }

    std::vector<SceneInput> mScenes;

private:
    std::set<std::string> mSeen;
};

constexpr const char* kFields[] = {"name", "path", "variant", "frame"};

}  // namespace

std::vector<std::string> parseSceneList(std::string_view text, const std::string& list) {
    std::vector<std::string> entries;
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    for (size_t start = 0, number = 1; start < text.size(); ++number) {
        const size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        while (!line.empty() && space(line.front())) line.remove_prefix(1);
        while (!line.empty() && space(line.back())) line.remove_suffix(1);
        if (line.empty() || line[0] == '#') continue;
        const std::string where = "@" + list + " line " + std::to_string(number);
        if (line[0] == '@') throw UserError(where + ": a list of scenes cannot name another list (" + std::string(line) + ")");
        if (line.find('\0') != std::string_view::npos) throw UserError(where + ": a NUL byte (not a list of file names?)");
        entries.emplace_back(line);
    }
    return entries;
}

SceneInput fileInput(const std::filesystem::path& file) { return {file, file.stem().string(), relativeStem(file)}; }

std::vector<SceneInput> expandSceneInputs(const std::vector<std::string>& inputs) {
    Collector collector;
    for (const std::string& input : inputs) collector.input(input, false);
    if (collector.mScenes.empty())
        throw UserError("no glTF scene (.gltf or .glb) in " + joinWords(inputs, "or"));
    return std::move(collector.mScenes);
}

namespace {

// A decimal number of at most 6 digits; nullopt for anything else.
std::optional<uint32_t> smallNumber(const std::string& text) {
    if (text.empty() || text.size() > 6 || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
        return std::nullopt;
    return uint32_t(std::stoul(text));
}

// --shard auto[/N]: the job array's index and count from the environment.
Shard shardFromEnvironment(const std::string& flag, const std::string& value, const EnvironmentLookup& env) {
    const auto variable = [&](const char* name) -> std::optional<std::string> {
        const char* text = env(name);
        if (!text || !*text) return std::nullopt;
        return std::string(text);
    };
    const auto numberOf = [&](const char* name, const std::string& text) {
        const std::optional<uint32_t> n = smallNumber(text);
        if (!n) throw UserError(flag + " " + value + ": " + name + " is '" + text + "', not a number");
        return *n;
    };
    std::optional<uint32_t> count;
    if (value != "auto") {
        count = smallNumber(value.substr(5));
        if (!count || *count < 1) throw UserError(flag + ": expected auto or auto/N with N >= 1, got '" + value + "'");
    }
    Shard shard;
    std::string from;
    if (const auto id = variable("SLURM_ARRAY_TASK_ID")) {
        // Slurm job arrays: ids from SLURM_ARRAY_TASK_MIN (--array=0-3 or 1-4), SLURM_ARRAY_TASK_COUNT tasks.
        const uint32_t first = variable("SLURM_ARRAY_TASK_MIN") ? numberOf("SLURM_ARRAY_TASK_MIN", *variable("SLURM_ARRAY_TASK_MIN")) : 0;
        const uint32_t task = numberOf("SLURM_ARRAY_TASK_ID", *id);
        if (task < first) throw UserError(flag + " " + value + ": SLURM_ARRAY_TASK_ID " + *id + " is below SLURM_ARRAY_TASK_MIN");
        shard.index = task - first + 1;
        if (!count && variable("SLURM_ARRAY_TASK_COUNT")) count = numberOf("SLURM_ARRAY_TASK_COUNT", *variable("SLURM_ARRAY_TASK_COUNT"));
        from = "SLURM_ARRAY_TASK_ID";
    } else if (const auto index = variable("JOB_COMPLETION_INDEX")) {
        // Kubernetes indexed jobs: 0 … completions − 1; the count is not in the environment.
        shard.index = numberOf("JOB_COMPLETION_INDEX", *index) + 1;
        from = "JOB_COMPLETION_INDEX";
    } else if (const auto node = variable("CI_NODE_INDEX")) {
        // GitLab CI's parallel jobs: 1 … CI_NODE_TOTAL.
        shard.index = numberOf("CI_NODE_INDEX", *node);
        if (!count && variable("CI_NODE_TOTAL")) count = numberOf("CI_NODE_TOTAL", *variable("CI_NODE_TOTAL"));
        from = "CI_NODE_INDEX";
    } else {
        throw UserError(flag + " " + value + ": none of SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX and CI_NODE_INDEX is set; "
                        "give I/N");
    }
    if (!count)
        throw UserError(flag + " " + value + ": " + from + " is set but the number of shards is not; give it: " + flag + " auto/N");
    shard.count = *count;
    if (shard.index < 1 || shard.index > shard.count)
        throw UserError(flag + " " + value + ": " + from + " gives shard " + std::to_string(shard.index) + " of " +
                        std::to_string(shard.count) + " (a sparse or offset array?)");
    return shard;
}

}  // namespace

Shard parseShard(const std::string& flag, const std::string& value, const EnvironmentLookup& env) {
    if (value == "auto" || value.rfind("auto/", 0) == 0) return shardFromEnvironment(flag, value, env);
    const size_t slash = value.find('/');
    const auto number = [&](const std::string& text) -> uint32_t { return smallNumber(text).value_or(0); };
    const Shard shard{slash == std::string::npos ? 0 : number(value.substr(0, slash)),
                      slash == std::string::npos ? 0 : number(value.substr(slash + 1))};
    if (shard.index < 1 || shard.count < 1 || shard.index > shard.count)
        throw UserError(flag + ": expected I/N with 1 <= I <= N (this machine's share of N), or auto, got '" + value + "'");
    return shard;
}

std::vector<SceneInput> shardOf(const std::vector<SceneInput>& scenes, Shard shard) {
    std::vector<SceneInput> out;
    for (size_t k = shard.index - 1; k < scenes.size(); k += shard.count) out.push_back(scenes[k]);
    return out;
}

void checkOutPattern(const std::string& pattern) {
    for (size_t open = pattern.find('{'); open != std::string::npos; open = pattern.find('{', open + 1)) {
        const size_t close = pattern.find('}', open);
        const std::string field = pattern.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
        if (close == std::string::npos || std::find(std::begin(kFields), std::end(kFields), field) == std::end(kFields))
            throw UserError("--out " + pattern + ": unknown field {" + field +
                            (close == std::string::npos ? "" : "}") + " (the fields are {name}, {path}, {variant} and {frame})");
    }
}

bool usesField(const std::string& pattern, const std::string& field) {
    return pattern.find("{" + field + "}") != std::string::npos;
}

std::string expandOutPattern(const std::string& pattern, const OutputFields& fields) {
    std::string frame;
    if (fields.frame) {
        frame = std::to_string(*fields.frame);
        if (frame.size() < 4) frame.insert(0, 4 - frame.size(), '0');
    }
    // The %d field first: the names put in below may hold a '%' of their own.
    const std::string text = fields.frame && !usesField(pattern, "frame") ? sequenceFileName(pattern, *fields.frame) : pattern;
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        const size_t close = text[i] == '{' ? text.find('}', i) : std::string::npos;
        if (close == std::string::npos) {
            out += text[i];
            continue;
        }
        const std::string field = text.substr(i + 1, close - i - 1);
        out += field == "name" ? fields.name : field == "path" ? fields.path : field == "variant" ? fields.variant : frame;
        i = close;
    }
    return out;
}

}  // namespace candela::app
