// The manual page and the shell completions (app/cli_manual.h) held to the flag table: each names
// every command, and under each command exactly the flags the table gives it; the roff has no
// stray request line. (tests/install parses the scripts with bash, zsh and fish and asks them.)

#include "cli_flags.h"
#include "cli_manual.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace candela::app {
namespace {

// The flags the table gives `command`.
std::set<std::string> flagsOf(const CommandInfo& command) {
    std::set<std::string> out;
    for (const Flag& flag : flagTable())
        if (flag.use(command.kind)) out.insert(flag.name);
    return out;
}

// `--name` as the manual page writes it: \-\-name.
std::string roffFlag(const std::string& flag) {
    std::string out;
    for (char c : flag) out += c == '-' ? std::string("\\-") : std::string(1, c);
    return out;
}

// The part of `text` from `begin` to the next `end` (or the end of `text`).
std::string section(const std::string& text, const std::string& begin, const std::string& end) {
    const size_t from = text.find(begin);
    if (from == std::string::npos) return "";
    const size_t to = text.find(end, from + begin.size());
    return text.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

TEST(CliManual, ManPageListsEachCommandsFlagsUnderIt) {
    const std::string man = manPage();
    for (const CommandInfo& command : commandTable()) {
        EXPECT_NE(man.find(".B candela " + command.name + "\n"), std::string::npos) << command.name << " in the synopsis";
        const std::string options = section(man, ".SS \"candela " + command.name + "\"", ".S");
        ASSERT_FALSE(options.empty()) << command.name;
        for (const Flag& flag : flagTable()) {
            const bool listed = options.find(".B " + roffFlag(flag.name) + "\n") != std::string::npos ||
                                options.find(".B " + roffFlag(flag.name) + " ") != std::string::npos;
            EXPECT_EQ(listed, flag.use(command.kind) != nullptr) << command.name << " " << flag.name;
        }
    }
}

TEST(CliManual, ManPageLinesAreTextOrKnownRequests) {
    const std::set<std::string> requests = {".TH", ".SH", ".SS", ".TP", ".B", ".I", ".IP", ".br", ".\\\""};
    std::istringstream lines(manPage());
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || (line[0] != '.' && line[0] != '\'')) continue;
        EXPECT_TRUE(requests.count(line.substr(0, line.find(' ')))) << line;
    }
}

TEST(CliManual, BashCompletionOffersEachCommandItsOwnFlags) {
    const std::string bash = bashCompletion();
    for (const CommandInfo& command : commandTable()) {
        const std::string line = section(bash, "        " + command.name + ") flags='", "\n");
        ASSERT_FALSE(line.empty()) << command.name;
        std::istringstream words(line.substr(line.find('\'') + 1, line.rfind('\'') - line.find('\'') - 1));
        std::set<std::string> offered;
        for (std::string word; words >> word;) offered.insert(word);
        std::set<std::string> expected = flagsOf(command);
        expected.insert("--help");
        EXPECT_EQ(offered, expected) << command.name;
    }
}

TEST(CliManual, ZshAndFishNameEachCommandsFlags) {
    const std::string zsh = zshCompletion(), fish = fishCompletion();
    for (const CommandInfo& command : commandTable()) {
        const std::string zshCase = section(zsh, "        " + command.name + ")\n", ";;");
        ASSERT_FALSE(zshCase.empty()) << command.name;
        for (const Flag& flag : flagTable()) {
            EXPECT_EQ(zshCase.find("'" + flag.name + "[") != std::string::npos, flag.use(command.kind) != nullptr)
                << "zsh " << command.name << " " << flag.name;
            const std::string fishLine =
                "complete -c candela -n '__fish_seen_subcommand_from " + command.name + "' -l " + flag.name.substr(2) + " ";
            EXPECT_EQ(fish.find(fishLine) != std::string::npos, flag.use(command.kind) != nullptr)
                << "fish " << command.name << " " << flag.name;
        }
    }
}

}  // namespace
}  // namespace candela::app
