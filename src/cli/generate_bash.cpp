// The bash completion from the CLI's own definitions: the commands, each command's options, the
// values of an option that takes one of a set (CLI11's IsMember: --backend, --quality), scene
// names where a command takes one, and file names elsewhere (timelines where a command takes a
// TIMELINE).
#include <string>
#include <vector>

#include "cli/cli_walk.h"
#include "cli/generate.h"
#include "scenes/registry.h"

namespace sdfreel {

namespace {

std::string words_of(CLI::App& cmd) {
  std::string w;
  for (const CLI::Option* o : all_options(cmd))
    for (const std::string& flag : flags_of(*o)) w += " " + flag;
  return w.empty() ? w : w.substr(1);
}

bool takes(CLI::App& cmd, const std::string& positional) {
  for (const CLI::Option* o : all_options(cmd))
    if (o->get_positional() && o->get_name(true) == positional) return true;
  return false;
}

// Options that take a value: the word after them is that value, not a positional.
std::string valued_options(CLI::App& app) {
  std::string w;
  for (CLI::App* cmd : all_commands(app))
    for (const CLI::Option* o : all_options(*cmd))
      if (!o->get_positional() && o->get_items_expected_max() != 0)
        for (const std::string& flag : flags_of(*o)) w += "|" + flag;
  return w.empty() ? "--" : w.substr(1);
}

// "TEXT:{cpu,gl,egl,osmesa}" -> "cpu gl egl osmesa"; "" for a type name without a set.
std::string choices(const std::string& type) {
  const size_t open = type.find(":{"), close = type.rfind('}');
  if (open == std::string::npos || close == std::string::npos || close < open) return "";
  std::string w = type.substr(open + 2, close - open - 2);
  for (char& c : w)
    if (c == ',') c = ' ';
  return w;
}

// A case arm "CMD:--option" per option of a set: the word after it completes from the set.
std::string choice_cases(CLI::App& app) {
  std::string arms;
  for (CLI::App* cmd : all_commands(app))
    for (const CLI::Option* o : all_options(*cmd)) {
      const std::string set = choices(o->get_type_name());
      if (set.empty() || o->get_positional()) continue;
      std::string pattern;
      for (const std::string& flag : flags_of(*o)) pattern += "|" + cmd->get_name() + ":" + flag;
      arms += "    " + pattern.substr(1) + ") COMPREPLY=($(compgen -W '" + set +
              "' -- \"$cur\")); return ;;\n";
    }
  return arms;
}

}  // namespace

std::string bash_completion(CLI::App& app) {
  std::string commands, cases, scenes;
  for (const SceneInfo& s : all_scenes()) scenes += (scenes.empty() ? "" : " ") + s.name;
  for (CLI::App* cmd : all_commands(app)) {
    commands += (commands.empty() ? "" : " ") + cmd->get_name();
    const char* what = takes(*cmd, "TIMELINE")                       ? "timeline"
                       : takes(*cmd, "NAME") || takes(*cmd, "SCENE") ? "scene"
                       : takes(*cmd, "KIND")                         ? "kind"
                                                                     : "file";
    cases += "    " + cmd->get_name() + ") opts='" + words_of(*cmd) + "'; what=" + what + " ;;\n";
  }
  return "# bash completion for sdfreel, made by `sdfreel generate complete-bash`\n"
         "_sdfreel() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
         "  local opts='' what=file\n"
         "  if [[ $COMP_CWORD -eq 1 ]]; then\n"
         "    COMPREPLY=($(compgen -W '" +
         commands +
         " --help --version' -- \"$cur\"))\n"
         "    return\n"
         "  fi\n"
         "  case ${COMP_WORDS[1]} in\n" +
         cases +
         "    *) return ;;\n"
         "  esac\n"
         "  if [[ $cur == -* ]]; then\n"
         "    COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\")); return\n"
         "  fi\n"
         "  case ${COMP_WORDS[1]}:$prev in\n" +
         choice_cases(app) +
         "  esac\n"
         "  case $prev in\n"
         "    " +
         valued_options(app) +
         ") what=file ;;\n"
         "  esac\n"
         "  case $what in\n"
         "    scene) COMPREPLY=($(compgen -W '" +
         scenes +
         "' -- \"$cur\")) ;;\n"
         "    kind) COMPREPLY=($(compgen -W 'man complete-bash' -- \"$cur\")) ;;\n"
         "    timeline) COMPREPLY=($(compgen -f -X '!*.toml' -- \"$cur\") $(compgen -d -- "
         "\"$cur\")) ;;\n"
         "    *) COMPREPLY=($(compgen -f -- \"$cur\")) ;;\n"
         "  esac\n"
         "}\n"
         "complete -o filenames -F _sdfreel sdfreel\n";
}

}  // namespace sdfreel
