// The `candela` executable: parses the command line and runs a subcommand. Every error reaches the
// user as one line on stderr and a non-zero exit code (failures.h).

#include "commands.h"
#include "failures.h"
#include "core/log.h"

#include <cstdio>

namespace candela::app {
namespace {

int run(const Command& command) {
    log::setVerbose(command.common().verbose);  // before anything loads: loaders print notes with --verbose
    switch (command.kind) {
        case Command::Kind::Help:
            std::fputs((command.helpCommand.empty() ? usageText() : commandHelp(command.helpCommand)).c_str(), stdout);
            return 0;
        case Command::Kind::Version: std::printf("%s\n", versionText().c_str()); return 0;
        case Command::Kind::Render: return runRender(command.render);
        case Command::Kind::View: return runView(command.view);
        case Command::Kind::Info: return runInfo(command.info);
        case Command::Kind::Bench: return runBench(command.bench, command.arguments);
        case Command::Kind::IblReport: return runIblReport(command.iblReport);
        case Command::Kind::Soak: return runSoak(command.soak);
        case Command::Kind::ScaleReport: return runScaleReport(command.scaleReport);
        case Command::Kind::QualityReport: return runQualityReport(command.qualityReport);
        case Command::Kind::Diff: return runDiff(command.diff);
    }
    return 1;
}

}  // namespace
}  // namespace candela::app

int main(int argc, char** argv) {
    using namespace candela::app;
    return exitCodeOf([&] { return run(parseCommandLine(std::vector<std::string>(argv + 1, argv + argc))); });
}
