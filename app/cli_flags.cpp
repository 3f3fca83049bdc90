// The flag table (cli_flags.h): every command's flags merged into one row per flag.

#include "cli_flags.h"

#include "core/errors.h"

#include <algorithm>
#include <map>
#include <memory>
#include <set>

namespace candela::app {
namespace {

// Every flag name, ordered so that each command's flags keep the order its own list declares them
// in (`candela COMMAND --help` lists them so). `lists[c]`: the names command c of commandTable()
// declares, in order. The lists are merged by placing, again and again, of the flags whose
// predecessors in every list are placed, the one declared first (by the earliest command). Two
// commands declaring two flags in opposite orders is an InternalError naming them.
std::vector<std::string> helpOrder(const std::vector<std::vector<std::string>>& lists) {
    std::map<std::string, size_t> rank;                 // the flag's first declaration
    std::map<std::string, std::set<std::string>> next;  // the flags some list declares right after it
    std::map<std::string, size_t> before;               // how many flags must come before it
    for (const std::vector<std::string>& list : lists)
        for (size_t i = 0; i < list.size(); ++i) {
            rank.emplace(list[i], rank.size());
            before[list[i]];
            if (i > 0 && next[list[i - 1]].insert(list[i]).second) ++before[list[i]];
        }
    std::set<std::pair<size_t, std::string>> ready;
    for (const auto& [name, count] : before)
        if (count == 0) ready.insert({rank.at(name), name});
    std::vector<std::string> order;
    while (!ready.empty()) {
        const std::string name = ready.begin()->second;
        ready.erase(ready.begin());
        order.push_back(name);
        for (const std::string& after : next[name])
            if (--before.at(after) == 0) ready.insert({rank.at(after), after});
    }
    if (order.size() == rank.size()) return order;
    for (size_t a = 0; a < lists.size(); ++a)
        for (size_t b = a + 1; b < lists.size(); ++b)
            for (size_t i = 0; i < lists[a].size(); ++i)
                for (size_t j = i + 1; j < lists[a].size(); ++j) {
                    const auto& other = lists[b];
                    const auto first = std::find(other.begin(), other.end(), lists[a][i]);
                    const auto second = std::find(other.begin(), other.end(), lists[a][j]);
                    if (first != other.end() && second != other.end() && second < first)
                        throw InternalError(commandTable()[a].name + " declares " + lists[a][i] + " before " +
                                            lists[a][j] + ", " + commandTable()[b].name + " after it; help cannot keep both");
                }
    throw InternalError("the commands declare their flags in orders that help cannot all keep");
}

using Setters = std::map<Command::Kind, Setter<Command>>;

// Adds `kind`'s use of a flag to its row: to a use that reads the same, else as a new use.
void addUse(Flag& flag, Setters& setters, Command::Kind kind, FlagSpec<Command>&& spec) {
    for (FlagUse& use : flag.uses)
        if (use.value == spec.value && use.help == spec.help && use.defaultValue == spec.defaultValue) {
            use.commands.bits |= CommandSet{kind}.bits;
            setters.emplace(kind, std::move(spec.set));
            return;
        }
    if (!flag.uses.empty() && (flag.choices != spec.choices || flag.otherForm != spec.otherForm))
        throw InternalError(flag.name + ": two commands accept different values");
    flag.choices = std::move(spec.choices);
    flag.otherForm = std::move(spec.otherForm);
    flag.uses.push_back({CommandSet{kind}, std::move(spec.value), std::move(spec.help), std::move(spec.defaultValue)});
    setters.emplace(kind, std::move(spec.set));
}

std::vector<Flag> makeFlagTable() {
    std::vector<std::vector<FlagSpec<Command>>> specs;
    std::vector<std::vector<std::string>> names;
    for (const CommandInfo& command : commandTable()) {
        specs.push_back(command.flags());
        names.emplace_back();
        for (const FlagSpec<Command>& spec : specs.back()) {
            if (std::find(names.back().begin(), names.back().end(), spec.name) != names.back().end())
                throw InternalError(command.name + " declares " + spec.name + " twice");
            names.back().push_back(spec.name);
        }
    }
    std::vector<Flag> flags;
    std::map<std::string, size_t> row;
    for (const std::string& name : helpOrder(names)) {
        row.emplace(name, flags.size());
        flags.push_back({.name = name});
    }
    std::vector<Setters> setters(flags.size());
    for (size_t c = 0; c < specs.size(); ++c) {
        const CommandInfo& command = commandTable()[c];
        for (FlagSpec<Command>& spec : specs[c])
            addUse(flags[row.at(spec.name)], setters[row.at(spec.name)], command.kind, std::move(spec));
    }
    for (size_t i = 0; i < flags.size(); ++i) {
        flags[i].set = [bound = std::make_shared<const Setters>(std::move(setters[i]))](Command& c, const std::string& flag,
                                                                                       const std::string& value) {
            bound->at(c.kind)(c, flag, value);
        };
    }
    return flags;
}

}  // namespace

const std::vector<Flag>& flagTable() {
    static const std::vector<Flag> flags = makeFlagTable();
    return flags;
}

const Flag* findFlag(std::string_view name) {
    for (const Flag& flag : flagTable())
        if (flag.name == name) return &flag;
    return nullptr;
}

const FlagUse* Flag::use(Command::Kind kind) const {
    for (const FlagUse& u : uses)
        if (u.commands.contains(kind)) return &u;
    return nullptr;
}

CommandSet Flag::commands() const {
    CommandSet all{};
    for (const FlagUse& u : uses) all.bits |= u.commands.bits;
    return all;
}

}  // namespace candela::app
