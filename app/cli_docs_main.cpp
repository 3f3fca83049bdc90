// candela_cli_docs OUT_DIR: writes the manual page and the shell completions generated from the
// flag table (cli_manual.h) into OUT_DIR — man1/candela.1, bash/candela, zsh/_candela,
// fish/candela.fish — for the build to install. Run by the build (app/CMakeLists.txt).

#include "cli_manual.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: candela_cli_docs OUT_DIR\n");
        return 2;
    }
    namespace app = candela::app;
    const std::filesystem::path out = argv[1];
    const std::pair<const char*, std::string> files[] = {{"man1/candela.1", app::manPage()},
                                                         {"bash/candela", app::bashCompletion()},
                                                         {"zsh/_candela", app::zshCompletion()},
                                                         {"fish/candela.fish", app::fishCompletion()}};
    try {
        for (const auto& [name, text] : files) {
            const std::filesystem::path path = out / name;
            std::filesystem::create_directories(path.parent_path());
            std::ofstream file(path, std::ios::binary);
            file << text;
            if (!file.flush()) {
                std::fprintf(stderr, "candela_cli_docs: cannot write %s\n", path.c_str());
                return 1;
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela_cli_docs: %s\n", e.what());
        return 1;
    }
    return 0;
}
