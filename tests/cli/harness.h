#pragma once
// Runs the built sdfreel binary (and stock ffmpeg tools) in scratch folders for end-to-end tests.
#include <string>
#include <vector>

namespace sdfreel::test {

struct RunResult {
  int status = -1;
  std::string out, err;
};

// Runs `command` through /bin/sh in `cwd`, capturing stdout and stderr.
RunResult run(const std::string& command, const std::string& cwd = ".");
// `sdfreel ARGS` (the binary this build made).
RunResult sdfreel(const std::string& args, const std::string& cwd = ".");
bool have_tool(const std::string& name);  // on PATH

std::string make_scratch_dir(const std::string& name);  // fresh, empty, under the temp folder
void write_file(const std::string& path, const std::string& text);
std::string read_file(const std::string& path);
std::vector<std::string> framemd5_data_lines(const std::string& text);  // lines not starting with #
std::string source_path(const std::string& rel);                        // path in the source tree

// A small sdf_morph timeline; `extra` is appended (more tables or keys).
std::string small_timeline(int frames, const std::string& codec = "ffv1",
                           const std::string& video = "small.mkv", const std::string& extra = "");

}  // namespace sdfreel::test
