#include "cli.h"

#include "cli_flags.h"
#include "core/errors.h"

#include <algorithm>

namespace candela::app {
namespace {

using Kind = Command::Kind;

template <class Self>
auto& commonOf(Self& command) {
    switch (command.kind) {
        case Kind::Render: return command.render.common;
        case Kind::View: return command.view.common;
        case Kind::Bench: return command.bench.common;
        case Kind::Info: return command.info.common;
        case Kind::IblReport: return command.iblReport.common;
        case Kind::Soak: return command.soak.common;
        case Kind::ScaleReport: return command.scaleReport.common;
        case Kind::QualityReport: return command.qualityReport.common;
        case Kind::Diff: return command.diff.common;
        case Kind::Help:
        case Kind::Version: break;
    }
    throw InternalError("help and version have no common options to set");
}

// Edits (insertions, deletions, substitutions, swaps of neighbours) that turn `a` into `b`.
size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The candidate `typed` was most likely meant as: the only one it begins (at least 3 letters
// after the dashes), else the nearest within a few edits (fewer for short names); "" for none.
std::string nearest(const std::string& typed, const std::vector<std::string>& candidates) {
    std::vector<std::string> extending;
    for (const std::string& candidate : candidates)
        if (typed.size() >= 5 && candidate.rfind(typed, 0) == 0) extending.push_back(candidate);
    if (extending.size() == 1) return extending.front();
    const size_t letters = typed.size() - std::min<size_t>(2, typed.find_first_not_of('-'));
    const size_t allowed = letters <= 4 ? 1 : letters <= 8 ? 2 : 3;
    std::string best;
    size_t bestDistance = allowed + 1;
    for (const std::string& candidate : candidates)
        if (const size_t distance = editDistance(typed, candidate); distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    return best;
}

// The one-line error for a flag the table does not have: the nearest flag of the command, else
// the nearest of another command.
std::string unknownFlagMessage(const std::string& flag, const CommandInfo& command) {
    std::vector<std::string> own, all;
    for (const Flag& f : flagTable()) {
        all.push_back(f.name);
        if (f.use(command.kind)) own.push_back(f.name);
    }
    const std::string prefix = "unknown flag " + flag + " for " + command.name;
    if (const std::string guess = nearest(flag, own); !guess.empty()) return prefix + " (did you mean " + guess + "?)";
    if (const std::string guess = nearest(flag, all); !guess.empty())
        return prefix + " (did you mean " + guess + "? it is a flag of " + commandList(findFlag(guess)->commands(), false) + ")";
    return prefix + " (candela " + command.name + " --help lists its flags)";
}

std::string unknownCommandMessage(const std::string& name) {
    std::vector<std::string> names;
    for (const CommandInfo& command : commandTable()) names.push_back(command.name);
    std::vector<std::string> candidates = names;
    candidates.insert(candidates.end(), {"--help", "--version"});
    const std::string guess = nearest(name, candidates);
    return "unknown command '" + name + "' (" + (guess.empty() ? "" : "did you mean " + guess + "? ") + "commands: " +
           joinWords(names, "and") + "; see candela --help)";
}

bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h"; }

}  // namespace

const CommonOptions& Command::common() const {
    static const CommonOptions defaults;
    return kind == Kind::Help || kind == Kind::Version ? defaults : commonOf(*this);
}

CommonOptions& Command::common() { return commonOf(*this); }

Command parseCommandLine(const std::vector<std::string>& args) {
    Command command;
    if (args.empty() || isHelp(args[0]) || args[0] == "help") {
        // `candela help COMMAND` is `candela COMMAND --help`.
        if (args.size() > 1 && args[0] == "help") {
            if (!findCommand(args[1])) throw UserError(unknownCommandMessage(args[1]));
            command.helpCommand = args[1];
        }
        return command;
    }
    if (args[0] == "--version") {
        if (args.size() > 1) throw UserError("unexpected argument '" + args[1] + "' after --version");
        command.kind = Kind::Version;
        return command;
    }
    const CommandInfo* info = findCommand(args[0]);
    if (!info) throw UserError(unknownCommandMessage(args[0]));
    if (std::any_of(args.begin() + 1, args.end(), isHelp)) {
        command.helpCommand = info->name;
        return command;
    }
    command.kind = info->kind;
    command.arguments.assign(args.begin() + 1, args.end());
    for (const Flag& flag : flagTable())
        if (const FlagUse* use = flag.use(command.kind); use && !use->defaultValue.empty()) flag.set(command, flag.name, use->defaultValue);

    for (size_t i = 1; i < args.size(); ++i) {
        std::string name = args[i];
        if (name.size() < 2 || name[0] != '-') {
            if (!info->argument)
                throw UserError("unexpected argument '" + name + "' for " + info->name + " (see candela " + info->name + " --help)");
            info->argument(command, name);
            continue;
        }
        std::optional<std::string> value;
        if (const size_t eq = name.find('='); name.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = name.substr(eq + 1);
            name.resize(eq);
        }
        const Flag* flag = findFlag(name);
        if (!flag) throw UserError(unknownFlagMessage(name, *info));
        if (!flag->use(command.kind))
            throw UserError(info->name + " does not take " + name + " (it is a flag of " + commandList(flag->commands(), false) + ")");
        if (flag->isSwitch()) {
            if (value) throw UserError(name + " takes no value");
            flag->set(command, name, "");
            continue;
        }
        if (!value) {
            if (i + 1 >= args.size()) throw UserError(name + " needs a value");
            value = args[++i];
        }
        flag->set(command, name, *value);
    }
    if (info->check) info->check(command);
    return command;
}

}  // namespace candela::app
