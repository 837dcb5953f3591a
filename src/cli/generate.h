#pragma once
// `sdfreel generate man|complete-bash` (after ripgrep's `rg --generate`): the man page and the
// bash completion, made from the same command and option definitions as `--help` (and checked
// against docs/cli.md by its test), so none of the three can drift from the others.
#include <CLI/CLI.hpp>
#include <string>

namespace sdfreel {

// The man page sdfreel(1) in roff (man(7) macros).
std::string man_page(CLI::App& app);

// A bash completion script: commands, each command's options, scene names, file names.
std::string bash_completion(CLI::App& app);

}  // namespace sdfreel
