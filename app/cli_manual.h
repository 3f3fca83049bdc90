#pragma once
// The manual page and the shell completions of `candela`, generated from the command and flag
// tables (cli_flags.h) as the help texts are, so they name exactly the commands and flags the
// parser takes, with the same descriptions, names and defaults. Written at build time by
// candela_cli_docs (cli_docs_main.cpp) and installed (docs/packaging.md). Pure, no Vulkan.

#include <string>

namespace candela::app {

// candela(1) in roff with the man(7) macros: name, synopsis, the commands, each command's flags,
// exit status, files, environment.
std::string manPage();
// A bash completion script (bash-completion's completions/ folder): commands, each command's
// flags, enum names, files for FILE values and folders for DIR values.
std::string bashCompletion();
// A zsh completion function (_candela, for a folder on $fpath), with the flags' descriptions.
std::string zshCompletion();
// A fish completion script (vendor_completions.d/candela.fish), with the flags' descriptions.
std::string fishCompletion();

}  // namespace candela::app
