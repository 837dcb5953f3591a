// `sdfreel generate man|complete-bash`: the man page or the bash completion, made from the
// commands' own definitions (cli/generate.h); the build installs both.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "cli/commands_impl.h"
#include "cli/generate.h"

namespace sdfreel {

void add_generate_command(CLI::App& app, int& status) {
  auto kind = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "generate", "print the man page (man) or the bash completion (complete-bash) of sdfreel");
  cmd->add_option("KIND", *kind, "man or complete-bash")
      ->required()
      ->check(CLI::IsMember({"man", "complete-bash"}));
  cmd->callback([&app, kind, &status] {
    const std::string text = *kind == "man" ? man_page(app) : bash_completion(app);
    std::fputs(text.c_str(), stdout);
    status = 0;
  });
}

}  // namespace sdfreel
