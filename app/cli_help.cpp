// The help texts, generated from the command and flag tables (cli_flags.h).

#include "cli.h"
#include "cli_flags.h"

#include <algorithm>
#include <map>

namespace candela::app {
namespace {

constexpr size_t kLineWidth = 100;
constexpr size_t kTextColumn = 24;

// `text` wrapped at spaces so that no line passes kLineWidth: the first line goes on from column
// `first`, the others are indented to `indent`.
std::string wrap(const std::string& text, size_t indent, size_t first) {
    std::string out;
    size_t column = first;
    bool lineEmpty = true;
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find(' ', at), text.size());
        const size_t length = end - at;
        if (!lineEmpty && column + 1 + length > kLineWidth) {
            out += "\n" + std::string(indent, ' ');
            column = indent;
            lineEmpty = true;
        }
        if (!lineEmpty) {
            out += ' ';
            ++column;
        }
        out.append(text, at, length);
        column += length;
        lineEmpty = false;
        at = end + 1;
    }
    return out;
}

// "  LEFT   TEXT…" with TEXT from kTextColumn on (on the next line when LEFT reaches it).
std::string row(const std::string& left, const std::string& text) {
    std::string out = "  " + left;
    out += out.size() + 1 > kTextColumn ? "\n" + std::string(kTextColumn, ' ') : std::string(kTextColumn - out.size(), ' ');
    return out + wrap(text, kTextColumn, kTextColumn) + "\n";
}

}  // namespace

std::string flagUsage(const Flag& flag, const FlagUse& use) {
    if (use.value != "{choices}") return flag.name + (use.value.empty() ? "" : " " + use.value);
    std::string names;
    for (const std::string& name : flag.choices) names += (names.empty() ? "" : "|") + name;
    return flag.name + " " + names;
}

std::string flagDescription(const Flag& flag, const FlagUse& use) {
    std::string text = use.help;
    if (const size_t at = text.find("{choices}"); at != std::string::npos)
        text.replace(at, 9, joinChoices(flag.choices, flag.otherForm));
    if (!use.defaultValue.empty()) text += " [" + use.defaultValue + "]";
    return text;
}

std::string versionText() { return "candela " CANDELA_VERSION; }

std::string commandHelp(std::string_view name) {
    const CommandInfo& command = *findCommand(name);
    std::string out = "usage: candela " + command.name + " " + command.arguments + "\n" +
                      wrap(command.summary, 0, 0) + "\n\nflags:\n";
    for (const Flag& flag : flagTable())
        if (const FlagUse* use = flag.use(command.kind)) out += row(flagUsage(flag, *use), flagDescription(flag, *use));
    out += row("-h, --help", "print this help");
    if (!command.notes.empty()) out += "\n" + wrap(command.notes, 0, 0) + "\n";
    return out;
}

std::string usageText() {
    std::string out = versionText() + ": a physically based renderer on Vulkan 1.3, built around a frame render graph\n\n"
                      "usage: candela COMMAND [flags]\n"
                      "       candela COMMAND --help   the command's flags only\n"
                      "       candela --version\n\ncommands:\n";
    for (const CommandInfo& command : commandTable())
        out += row(command.name + (command.kind == Command::Kind::View ? " [SCENE]" : ""), command.summary);
    // The flags grouped by the commands that take them, groups in the order of their first flag.
    std::vector<CommandSet> order;
    std::map<uint32_t, std::string> groups;
    for (const Flag& flag : flagTable()) {
        const CommandSet set = flag.commands();
        if (!groups.count(set.bits)) order.push_back(set);
        std::string& group = groups[set.bits];
        std::string previous;
        for (const FlagUse& use : flag.uses) {
            const std::string left = flagUsage(flag, use);
            const std::string text = flagDescription(flag, use);
            group += row(left == previous ? "" : left, flag.uses.size() > 1 ? commandList(use.commands) + ": " + text : text);
            previous = left;
        }
    }
    for (const CommandSet& set : order) out += "\nflags of " + commandList(set) + ":\n" + groups[set.bits];
    return out;
}

}  // namespace candela::app
