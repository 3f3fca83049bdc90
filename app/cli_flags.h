#pragma once
// The command line's two tables: the commands, and the flags. Each command declares its flags in
// its own file (render_cli.h, ...: FlagSpec lists assembled from the groups of flag_groups.h);
// flagTable() merges them into one row per flag, in an order that keeps each command's own. The
// parser, `candela --help`, `candela COMMAND --help` and the tests all read these two tables.
// (The commands are assembled in cli_commands.cpp, the flags merged in cli_flags.cpp.)

#include "cli.h"
#include "flag_spec.h"

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace candela::app {

// A set of commands (Command::Kind).
struct CommandSet {
    uint32_t bits = 0;
    constexpr CommandSet(std::initializer_list<Command::Kind> kinds) {
        for (Command::Kind kind : kinds) bits |= 1u << unsigned(kind);
    }
    constexpr bool contains(Command::Kind kind) const { return (bits >> unsigned(kind)) & 1u; }
    bool operator==(const CommandSet&) const = default;
};

struct CommandInfo {
    Command::Kind kind;
    std::string name;       // "render"
    std::string arguments;  // what follows the name in the usage line: "[SCENE] [flags]"
    std::string summary;    // what the command does
    std::string notes;      // printed after the flags in the command's help ("" none)
    // The command's flags, their setters bound to its options in Command.
    std::function<std::vector<FlagSpec<Command>>()> flags;
    // Takes an argument that is not a flag (render's SCENE..., view's SCENE, diff's A B); null:
    // the command takes none.
    std::function<void(Command&, const std::string&)> argument;
    // The checks that involve more than one flag, after the last argument; null: none.
    std::function<void(const Command&)> check;
};

// Every command, in the order help lists them.
const std::vector<CommandInfo>& commandTable();
// The command named `name`; null for none.
const CommandInfo* findCommand(std::string_view name);
// The commands of `set` as "render, view and bench", or "every command"; with `allBut`, a set of
// more than four as "every command but info".
std::string commandList(CommandSet set, bool allBut = true);

// What a flag means to some of the commands that take it.
struct FlagUse {
    CommandSet commands;
    std::string value;  // the value's name in help ("N", "FILE"; "{choices}": "on|off"); "" for a switch
    // What the flag does; "{choices}" stands for the accepted names of an enum-valued flag.
    std::string help;
    // The value these commands have without the flag, as the flag would give it ("" none, or a
    // default that is no value of the flag, which `help` then describes). The parser applies it
    // before the arguments, so help and behaviour share this one declaration.
    std::string defaultValue;
};

// One row per flag: the uses of every command that takes it, merged (commands whose use reads the
// same share one FlagUse; uses in the order of their first command in commandTable()).
struct Flag {
    std::string name;           // "--frames"
    std::vector<FlagUse> uses;  // disjoint command sets
    // Enum-valued flags: the names accepted (from the enum's own table), and a form accepted
    // besides them ("#rrggbb"); help and errors list exactly these.
    std::vector<std::string> choices;
    std::string otherForm;
    // Parses `value` ("" for a switch) into the options of `command` (whose kind takes the flag),
    // with that command's setter; a UserError naming the flag (`name`, passed as `flag`) when it
    // is malformed.
    std::function<void(Command& command, const std::string& flag, const std::string& value)> set;

    bool isSwitch() const { return uses.front().value.empty(); }
    // The use for `kind`; null when `kind` does not take the flag.
    const FlagUse* use(Command::Kind kind) const;
    // The commands that take the flag.
    CommandSet commands() const;
};

// "--flag VALUE" as help shows it; an enum-valued flag's VALUE is its names: "--cull on|off".
std::string flagUsage(const Flag& flag, const FlagUse& use);
// What the flag does for the commands of `use`, with the names it accepts and its default.
std::string flagDescription(const Flag& flag, const FlagUse& use);

// Every flag, in the order help lists them: each command's flags in the order its list declares
// them. -h/--help and --version are not in it.
const std::vector<Flag>& flagTable();
// The flag named `name`; null for none.
const Flag* findFlag(std::string_view name);

}  // namespace candela::app
