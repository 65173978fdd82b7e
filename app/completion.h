// Bash completion for `prism`, written from the command line's own CLI11
// definitions so that it names exactly the commands and options the program
// takes. The build runs `prism --bash-completion` (a hidden option) and
// installs its output (docs/installing.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace prism {

// A bash script defining the completion function `_<program>` and binding it
// with `complete -F`: subcommand names and aliases, each command's options,
// file names for its positional arguments and for options taking a path,
// the choices of options checked against a set, nothing for numbers. Plain
// bash (compgen), without the bash-completion package's helpers. Options and
// commands in no group (hidden, as this one's own option) are left out.
// `fileAtTop`: the program also takes a file where a subcommand would be
// (`prism SCENE` opens the previewer), so file names are offered there too.
std::string bashCompletionScript(const CLI::App& app, const std::string& program, bool fileAtTop);

// Adds the hidden flag `--bash-completion` to `app`: print the script to
// standard output and exit 0 (as --version does). The script is written when
// the flag is parsed, so it has every subcommand added by then.
void addBashCompletionFlag(CLI::App& app, const std::string& program, bool fileAtTop);

} // namespace prism
