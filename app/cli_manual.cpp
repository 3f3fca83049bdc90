// The manual page and shell completions (cli_manual.h), from the command and flag tables.

#include "cli_manual.h"

#include "cli.h"
#include "cli_flags.h"

#include <algorithm>
#include <string_view>
#include <vector>

namespace candela::app {
namespace {

// How a flag's value completes: a file, a folder, one of its names, or nothing to offer.
enum class ValueKind { None, File, Folder, Choice, Free };

ValueKind valueKind(const Flag& flag, const FlagUse& use) {
    if (use.value.empty()) return ValueKind::None;
    if (!flag.choices.empty()) return ValueKind::Choice;
    if (use.value == "FILE") return ValueKind::File;
    if (use.value == "DIR") return ValueKind::Folder;
    return ValueKind::Free;
}

// `words` separated by spaces.
std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
}

// The commands' names, in help's order.
std::vector<std::string> commandNames() {
    std::vector<std::string> names;
    for (const CommandInfo& command : commandTable()) names.push_back(command.name);
    return names;
}

// The first clause of `text` (up to "; ", ": ", " (" or " ["), at most 80 characters: a completion
// menu's one-line description.
std::string shortDescription(const std::string& text) {
    size_t end = text.size();
    for (std::string_view stop : {"; ", ": ", " (", " ["})
        if (const size_t at = text.find(stop); at != std::string::npos && at > 0) end = std::min(end, at);
    std::string out = text.substr(0, end);
    if (out.size() > 80) out = out.substr(0, 77) + "...";
    return out;
}

// `text` in single quotes for sh, zsh and fish ('it'\''s').
std::string shellQuoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// `text` as roff body text: backslashes escaped, every hyphen as \- (so flags print, and copy, as
// ASCII hyphens), and no line starting with a control character.
std::string roff(const std::string& text) {
    std::string out;
    bool lineStart = true;
    for (char c : text) {
        if (lineStart && (c == '.' || c == '\'')) out += "\\&";  // else a request
        if (c == '\\') out += "\\e";
        else if (c == '-') out += "\\-";
        else out += c;
        lineStart = c == '\n';
    }
    return out;
}

// The flags a command takes with their use for it, in help's order.
std::vector<std::pair<const Flag*, const FlagUse*>> flagsOf(const CommandInfo& command) {
    std::vector<std::pair<const Flag*, const FlagUse*>> out;
    for (const Flag& flag : flagTable())
        if (const FlagUse* use = flag.use(command.kind)) out.emplace_back(&flag, use);
    return out;
}

}  // namespace

std::string manPage() {
    std::string out = ".\\\" Generated from candela's flag table (app/cli_manual.cpp); do not edit.\n"
                      ".TH CANDELA 1 \"\" \"" + versionText() + "\" \"User Commands\"\n"
                      ".SH NAME\ncandela \\- a physically based renderer on Vulkan 1.3, built around a frame render graph\n"
                      ".SH SYNOPSIS\n";
    for (const CommandInfo& command : commandTable())
        out += ".B candela " + command.name + "\n" + roff(command.arguments) + "\n.br\n";
    out += ".B candela\n\\-\\-help | \\-\\-version\n"
           ".SH DESCRIPTION\n"
           "Candela renders glTF 2.0 scenes with image-based lighting, headless to image files or in an "
           "interactive viewer. Every command takes \\fB\\-\\-help\\fR to list its own flags. A malformed "
           "flag, a missing file or a malformed input is reported as one line naming the flag or the file "
           "and the problem.\n"
           ".SH COMMANDS\n";
    for (const CommandInfo& command : commandTable()) {
        out += ".TP\n.B " + command.name + "\n" + roff(command.summary) + "\n";
        if (!command.notes.empty()) out += ".IP\n" + roff(command.notes) + "\n";
    }
    out += ".SH OPTIONS\n";
    for (const CommandInfo& command : commandTable()) {
        out += ".SS \"candela " + command.name + "\"\n";
        for (const auto& [flag, use] : flagsOf(command))
            out += ".TP\n.B " + roff(flagUsage(*flag, *use)) + "\n" + roff(flagDescription(*flag, *use)) + "\n";
        out += ".TP\n.B \\-h, \\-\\-help\nprint the command's flags\n";
    }
    out += ".SH EXIT STATUS\n"
           ".TP\n.B 0\nsuccess\n"
           ".TP\n.B 1\nan internal error or a failed Vulkan call; \\fBdiff\\fR: a pair of images differs by more "
           "than its thresholds allow, is missing one side or differs in size\n"
           ".TP\n.B 2\nbad input: a malformed flag, a missing or malformed file (the one line on standard error "
           "names it)\n"
           ".TP\n.B 3\nthe Khronos validation layer reported messages (\\fB\\-\\-validate\\fR)\n"
           ".TP\n.B 4\nout of device memory, or over \\fB\\-\\-memory\\-budget\\fR\n"
           ".SH FILES\n"
           ".TP\n.I $XDG_CACHE_HOME/candela\\fR, else \\fI$HOME/.cache/candela\n"
           "The pipeline cache and the IBL maps' cache (\\fB\\-\\-pipeline\\-cache\\fR, \\fB\\-\\-ibl\\-cache\\fR).\n"
           ".SH ENVIRONMENT\n"
           ".TP\n.B VK_ICD_FILENAMES\nthe Vulkan driver to use, as for any Vulkan program (e.g. Mesa's lavapipe "
           "for headless rendering on the CPU)\n"
           ".TP\n.B CANDELA_DEVICE\nthe device to use when \\fB\\-\\-device\\fR is not given (the same selector; "
           "\\fBswiftshader\\fR adds the SwiftShader driver of Debian's chromium package)\n"
           ".SH SEE ALSO\nThe documentation installed with Candela (README.md and docs/).\n";
    return out;
}

std::string bashCompletion() {
    const std::vector<std::string> names = commandNames();
    std::string flags, values;
    for (const CommandInfo& command : commandTable()) {
        std::vector<std::string> list;
        for (const auto& [flag, use] : flagsOf(command)) {
            list.push_back(flag->name);
            const std::string key = "        " + command.name + ":" + flag->name + ") ";
            switch (valueKind(*flag, *use)) {
                case ValueKind::None: break;
                case ValueKind::File: values += key + "COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n"; break;
                case ValueKind::Folder: values += key + "COMPREPLY=($(compgen -d -- \"$cur\")); return ;;\n"; break;
                case ValueKind::Choice:
                    values += key + "COMPREPLY=($(compgen -W " + shellQuoted(joined(flag->choices)) + " -- \"$cur\")); return ;;\n";
                    break;
                case ValueKind::Free: values += key + "return ;;\n"; break;
            }
        }
        list.push_back("--help");
        flags += "        " + command.name + ") flags=" + shellQuoted(joined(list)) + " ;;\n";
    }
    return "# bash completion for candela, generated from its flag table (app/cli_manual.cpp); do not edit.\n"
           "_candela() {\n"
           "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
           "    if ((COMP_CWORD == 1)); then\n"
           "        COMPREPLY=($(compgen -W " + shellQuoted(joined(names) + " --help --version") + " -- \"$cur\"))\n"
           "        return\n"
           "    fi\n"
           "    local command=${COMP_WORDS[1]} flags=\n"
           "    case $command:$prev in\n" + values +
           "    esac\n"
           "    case $command in\n" + flags +
           "        *) return ;;\n"
           "    esac\n"
           "    if [[ $cur == -* ]]; then\n"
           "        COMPREPLY=($(compgen -W \"$flags\" -- \"$cur\"))\n"
           "    else\n"
           "        COMPREPLY=($(compgen -f -- \"$cur\"))\n"
           "    fi\n"
           "}\n"
           "complete -o filenames -F _candela candela\n";
}

std::string zshCompletion() {
    // An _arguments spec's description is in [...]: escape the brackets and the colon.
    const auto described = [](const std::string& text) {
        std::string out;
        for (char c : shortDescription(text)) out += (c == '[' || c == ']' || c == ':' || c == '\\') ? std::string("\\") + c : std::string(1, c);
        return out;
    };
    std::string out = "#compdef candela\n"
                      "# zsh completion for candela, generated from its flag table (app/cli_manual.cpp); do not edit.\n"
                      "_candela() {\n"
                      "    local -a commands\n"
                      "    commands=(\n";
    for (const CommandInfo& command : commandTable())
        out += "        " + shellQuoted(command.name + ":" + described(command.summary)) + "\n";
    out += "    )\n"
           "    if (( CURRENT == 2 )); then\n"
           "        _describe 'command' commands\n"
           "        return\n"
           "    fi\n"
           "    local command=$words[2]\n"
           "    shift words\n"
           "    (( CURRENT-- ))\n"
           "    case $command in\n";
    for (const CommandInfo& command : commandTable()) {
        out += "        " + command.name + ")\n            _arguments -s \\\n";
        for (const auto& [flag, use] : flagsOf(command)) {
            std::string spec = flag->name + "[" + described(flagDescription(*flag, *use)) + "]";
            switch (valueKind(*flag, *use)) {
                case ValueKind::None: break;
                case ValueKind::File: spec += ":" + use->value + ":_files"; break;
                case ValueKind::Folder: spec += ":" + use->value + ":_files -/"; break;
                case ValueKind::Choice: spec += ":value:(" + joined(flag->choices) + ")"; break;
                case ValueKind::Free: spec += ":" + use->value + ": "; break;
            }
            out += "                " + shellQuoted(spec) + " \\\n";
        }
        out += "                " + shellQuoted("(- *)--help[print the command's flags]");
        if (command.argument) out += " \\\n                " + shellQuoted("*:file:_files");
        out += "\n            ;;\n";
    }
    out += "    esac\n"
           "}\n"
           "_candela \"$@\"\n";
    return out;
}

std::string fishCompletion() {
    std::string out = "# fish completion for candela, generated from its flag table (app/cli_manual.cpp); do not edit.\n"
                      "complete -c candela -f\n";
    const std::vector<std::string> names = commandNames();
    for (const CommandInfo& command : commandTable())
        out += "complete -c candela -n " + shellQuoted("not __fish_seen_subcommand_from " + joined(names)) + " -a " +
               command.name + " -d " + shellQuoted(shortDescription(command.summary)) + "\n";
    for (const CommandInfo& command : commandTable()) {
        const std::string when = " -n " + shellQuoted("__fish_seen_subcommand_from " + command.name);
        for (const auto& [flag, use] : flagsOf(command)) {
            std::string line = "complete -c candela" + when + " -l " + flag->name.substr(2);
            switch (valueKind(*flag, *use)) {
                case ValueKind::None: break;
                case ValueKind::File: line += " -r -F"; break;
                case ValueKind::Folder: line += " -r -x -a '(__fish_complete_directories)'"; break;
                case ValueKind::Choice: line += " -r -x -a " + shellQuoted(joined(flag->choices)); break;
                case ValueKind::Free: line += " -r -x"; break;
            }
            out += line + " -d " + shellQuoted(shortDescription(flagDescription(*flag, *use))) + "\n";
        }
        if (command.argument) out += "complete -c candela" + when + " -F\n";
    }
    return out;
}

}  // namespace candela::app
