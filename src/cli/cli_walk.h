#pragma once
// Walking the CLI's own definitions (`sdfreel generate`): every command, every option of one, and
// an option's flags as a user types them.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace sdfreel {

// Every command (CLI11's get_subcommands() without a filter lists only the parsed ones).
inline std::vector<CLI::App*> all_commands(CLI::App& app) {
  return app.get_subcommands([](CLI::App*) { return true; });
}

// Every option of `cmd`, positionals included, in the order they were defined.
inline std::vector<const CLI::Option*> all_options(const CLI::App& cmd) {
  return cmd.get_options([](const CLI::Option*) { return true; });
}

// "-o", then "--output": the short names, then the long ones.
inline std::vector<std::string> flags_of(const CLI::Option& o) {
  std::vector<std::string> flags;
  for (const std::string& s : o.get_snames()) flags.push_back("-" + s);
  for (const std::string& l : o.get_lnames()) flags.push_back("--" + l);
  return flags;
}

}  // namespace sdfreel
