#pragma once
// Where sdfreel's data files (the GLSL shaders, the OCIO config) are at run time.
#include <filesystem>
#include <string>
#include <vector>

namespace sdfreel {

// Places to look for `relative` (e.g. "shaders", "ocio/config.ocio"), best first: the install
// prefix's share/sdfreel/ next to the executable (<prefix>/bin/sdfreel); then, only for an
// executable inside its own build tree, the source tree. An installed or copied sdfreel never
// reads the source tree it was built from, so a package missing a file fails instead of working
// by accident on the build machine.
std::vector<std::filesystem::path> data_file_candidates(const std::string& relative);

// Places to look for a module sdfreel opens at run time (e.g. "sdfreel_image_oiio.so"), best
// first: <prefix>/lib/sdfreel/ next to the executable; then, only for an executable inside its
// build tree, the build tree's lib/sdfreel/.
std::vector<std::filesystem::path> module_file_candidates(const std::string& name);

}  // namespace sdfreel
