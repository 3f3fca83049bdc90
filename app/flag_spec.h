#pragma once
// A flag as one command declares it (FlagSpec<O>): its text in help and a setter bound to the
// options struct O it writes. A flag group is written for the struct it fills (SceneOptions,
// CommonOptions...); bindTo() hands it to a command whose options hold that struct as a base or a
// member, and cli_commands.cpp binds each command's list to Command. The flag table (cli_flags.h)
// merges every command's specs into one row per flag.

#include "cli_values.h"

#include <concepts>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace candela::app {

// A setter's flag name and value, as its lambdas take them.
using Str = const std::string&;

// Parses `value` ("" for a switch) into the options; a UserError naming `flag` when malformed.
template <class O>
using Setter = std::function<void(O& options, const std::string& flag, const std::string& value)>;

template <class O>
struct FlagSpec {
    std::string name;          // "--frames"
    std::string value;         // the value's name in help ("N"; "{choices}": "on|off"); "" for a switch
    std::string help;          // what it does; "{choices}" stands for the accepted names
    std::string defaultValue;  // applied before the arguments and shown in help ("" none)
    Setter<O> set;
    std::vector<std::string> choices;  // enum-valued flags: the names accepted
    std::string otherForm;             // a form accepted besides them ("#rrggbb")
};

// `specs` with each setter applied to the part of O that `part(O&)` returns.
template <class O, class Part, class Select>
std::vector<FlagSpec<O>> rebind(std::vector<FlagSpec<Part>> specs, Select part) {
    std::vector<FlagSpec<O>> out;
    out.reserve(specs.size());
    for (FlagSpec<Part>& s : specs) {
        Setter<O> set = [set = std::move(s.set), part](O& o, const std::string& flag, const std::string& value) {
            set(part(o), flag, value);
        };
        out.push_back({std::move(s.name), std::move(s.value), std::move(s.help), std::move(s.defaultValue), std::move(set),
                       std::move(s.choices), std::move(s.otherForm)});
    }
    return out;
}

// A group written for `Part`, bound to options O that hold it as the member `member` (of O or of
// a base of O): bindTo<RenderOptions>(&RenderOptions::common, deviceFlags(true)).
template <class O, class Part, class Owner>
    requires std::derived_from<O, Owner>
std::vector<FlagSpec<O>> bindTo(Part Owner::*member, std::vector<FlagSpec<Part>> specs) {
    return rebind<O>(std::move(specs), [member](O& o) -> Part& { return o.*member; });
}

// A group written for `Part`, bound to options O derived from it.
template <class O, class Part>
    requires std::derived_from<O, Part>
std::vector<FlagSpec<O>> bindTo(std::vector<FlagSpec<Part>> specs) {
    return rebind<O>(std::move(specs), [](O& o) -> Part& { return o; });
}

// Appends `more` to `specs`.
template <class O>
void append(std::vector<FlagSpec<O>>& specs, std::vector<FlagSpec<O>> more) {
    for (FlagSpec<O>& s : more) specs.push_back(std::move(s));
}

// ---- setters ----

// options.*member = parse(flag, value).
template <class O, class T, class Parse>
Setter<O> parsed(T O::*member, Parse parse) {
    return [member, parse](O& o, const std::string& flag, const std::string& value) { o.*member = parse(flag, value); };
}

// A switch: options.*member = on.
template <class O>
Setter<O> setsTo(bool O::*member, bool on) {
    return [member, on](O& o, const std::string&, const std::string&) { o.*member = on; };
}

// options.*member = the value named in `names`.
template <class O, class T, class E, size_t N>
Setter<O> chosen(T O::*member, const std::pair<E, const char*> (&names)[N]) {
    return [member, &names](O& o, const std::string& flag, const std::string& value) {
        o.*member = parseChoice(flag, names, value);
    };
}

// An enum-valued flag: the setter of `member` and the names it accepts, from one names table.
template <class O, class T, class E, size_t N>
FlagSpec<O> choiceFlag(std::string name, std::string value, std::string help, std::string defaultValue, T O::*member,
                       const std::pair<E, const char*> (&names)[N]) {
    return {std::move(name), std::move(value), std::move(help), std::move(defaultValue), chosen(member, names), namesOf(names)};
}

}  // namespace candela::app
