#pragma once
// Command-line parsing for the `candela` executable. Pure (no Vulkan), unit-tested.
// Every malformed argument throws candela::UserError with a one-line message naming the flag.
// The flags — name, value, help, default, the commands that take them and how each is parsed —
// are declared by each command in its own file (render_cli.h, view_cli.h, ...: its options struct
// and its flag list) and merged into the flag table (cli_flags.h); Command holds the parsed values.

#include "bench_cli.h"
#include "diff_cli.h"
#include "ibl_report_cli.h"
#include "info_cli.h"
#include "quality_report_cli.h"
#include "render_cli.h"
#include "scale_report_cli.h"
#include "soak_cli.h"
#include "view_cli.h"

#include <string>
#include <string_view>
#include <vector>

namespace candela::app {

struct Command {
    enum class Kind { Help, Render, View, Info, Bench, IblReport, Soak, ScaleReport, QualityReport, Diff, Version } kind = Kind::Help;
    std::string helpCommand;  // Help: the command whose flags to list ("" for `candela --help`)
    RenderOptions render;
    ViewOptions view;
    BenchOptions bench;
    InfoOptions info;
    IblReportOptions iblReport;
    SoakOptions soak;
    ScaleReportOptions scaleReport;
    QualityReportOptions qualityReport;
    DiffOptions diff;
    // The command line after the command's name, as given (what `bench --cold` passes on to render).
    std::vector<std::string> arguments;
    // The common options of the command (defaults for help and version).
    const CommonOptions& common() const;
    CommonOptions& common();
    bool operator==(const Command&) const = default;
};

// Parses argv[1..]. No arguments, --help or -h → Kind::Help (with a command: that command's
// help); --version → Kind::Version.
Command parseCommandLine(const std::vector<std::string>& args);

// `candela --help`: the commands and every flag, grouped by the commands that take them.
std::string usageText();
// `candela COMMAND --help`: the flags of `command` only. Precondition: `command` is a command name.
std::string commandHelp(std::string_view command);
// `candela --version`: "candela 0.3.0" (CMake's PROJECT_VERSION).
std::string versionText();

}  // namespace candela::app
