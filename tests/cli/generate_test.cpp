// `sdfreel generate man|complete-bash` against `--help`: the man page names every command and
// every option, man renders it without a warning, and the bash completion completes commands,
// options, the values of an option of a set, scene names and timelines.
#include <gtest/gtest.h>

#include <string>

#include "cli/harness.h"
#include "cli/help_text.h"

namespace sdfreel::test {
namespace {

// Roff's spelling of an option: every '-' escaped.
std::string roff_name(const std::string& option) {
  std::string out;
  for (const char c : option) out += c == '-' ? std::string("\\-") : std::string(1, c);
  return out;
}

TEST(GenerateMan, NamesEveryCommandAndEveryOptionOfHelp) {
  const RunResult man = run_sdfreel("generate man");
  ASSERT_EQ(man.status, 0) << man.err;
  EXPECT_EQ(man.out.rfind(".TH SDFREEL 1 ", 0), 0u) << man.out.substr(0, 80);
  const std::vector<std::string> cmds = commands();
  ASSERT_GE(cmds.size(), 10u);
  for (const std::string& cmd : cmds) {
    const size_t at = man.out.find(".SS \"sdfreel " + cmd + " ");
    ASSERT_NE(at, std::string::npos) << cmd << " has no section in the man page";
    const size_t end = man.out.find(".SS ", at + 1);
    const std::string section = man.out.substr(at, end == std::string::npos ? end : end - at);
    for (const auto& names : options_of(cmd))
      for (const std::string& n : names)
        EXPECT_NE(section.find("\\fB" + roff_name(n) + "\\fR"), std::string::npos)
            << cmd << " " << n << " is not in its man page section";
  }
  for (const char* part : {".SH EXIT STATUS", ".SH ENVIRONMENT", ".SH FILES", ".SH SEE ALSO"})
    EXPECT_NE(man.out.find(part), std::string::npos) << part;
}

TEST(GenerateMan, ManRendersItWithoutAWarning) {
  if (!have_tool("man")) GTEST_SKIP() << "man is not installed (scripts/install-deps.sh --test)";
  const std::string dir = scratch_dir("generate_man");
  ASSERT_EQ(run_sdfreel("generate man > " + dir + "/sdfreel.1").status, 0);
  const RunResult shown = run("man --warnings -l " + dir + "/sdfreel.1", ".", "MANWIDTH=80 ");
  EXPECT_EQ(shown.status, 0) << shown.err;
  EXPECT_EQ(shown.err, "") << "man's warnings";
  for (const char* part : {"SDFREEL(1)", "EXIT STATUS", "sdfreel render TIMELINE [options]",
                           "--resume", "SDFREEL_CACHE_DIR"})
    EXPECT_NE(shown.out.find(part), std::string::npos) << part << " is not on the shown page";
}

// What bash's completion offers for the words of `line` (the last one being completed).
std::string completions(const std::string& script, const std::string& line) {
  const RunResult r =
      run("bash -c 'source " + script + "; read -ra COMP_WORDS <<< \"" + line + "\"; " +
              (line.back() == ' ' ? "COMP_WORDS+=(\"\"); " : "") +
              "COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _sdfreel; echo \"${COMPREPLY[*]}\"'",
          source_path(""));
  EXPECT_EQ(r.status, 0) << r.err;
  return r.out;
}

TEST(GenerateBash, CompletesCommandsOptionsScenesAndTimelines) {
  if (!have_tool("bash")) GTEST_SKIP() << "no bash";
  const std::string script = scratch_dir("generate_bash") + "/sdfreel";
  ASSERT_EQ(run_sdfreel("generate complete-bash > " + script).status, 0);
  EXPECT_EQ(completions(script, "sdfreel ren"), "render\n");
  EXPECT_EQ(completions(script, "sdfreel s"), "still sheet scenes slurm\n");
  EXPECT_EQ(completions(script, "sdfreel render --fr"), "--frames\n");
  EXPECT_EQ(completions(script, "sdfreel still --sam"), "--sample-counts --samples\n");
  EXPECT_EQ(completions(script, "sdfreel scenes water"), "water_lily\n");
  EXPECT_EQ(completions(script, "sdfreel generate "), "man complete-bash\n");
  EXPECT_EQ(completions(script, "sdfreel render --quality f"), "final\n");
  EXPECT_EQ(completions(script, "sdfreel still --backend "), "cpu gl egl osmesa\n");
  EXPECT_EQ(completions(script, "sdfreel render timelines/water_lily_f"),
            "timelines/water_lily_flythrough.toml\n");
  // Every option of every command is offered after its command.
  for (const std::string& cmd : commands())
    for (const auto& names : options_of(cmd))
      EXPECT_NE(completions(script, "sdfreel " + cmd + " -").find(names.back()), std::string::npos)
          << cmd << " " << names.back();
}

TEST(Generate, AnUnknownKindIsBadUsage) {
  const RunResult r = run_sdfreel("generate manual");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace sdfreel::test
