#pragma once
// Scratch folders and whole-file reads and writes for tests, and paths into the source tree.
#include <string>

namespace sdfreel::test {

std::string scratch_dir(const std::string& name);  // fresh and empty, under the temp folder
void write_file(const std::string& path, const std::string& text);
std::string read_file(const std::string& path);   // "" when missing
std::string source_path(const std::string& rel);  // path in the source tree

}  // namespace sdfreel::test
