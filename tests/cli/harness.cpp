#include "cli/harness.h"

#include <cstdio>
#include <sstream>

namespace sdfreel::test {

std::vector<std::string> framemd5_data_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line))
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

std::string small_timeline(int frames, const std::string& codec, const std::string& video,
                           const std::string& extra) {
  char duration[32];
  std::snprintf(duration, sizeof duration, "%.6f", frames / 10.0);
  return std::string("[video]\nscene = \"sdf_morph\"\nfps = 10\nduration = ") + duration +
         "\nresolution = [64, 36]\nsamples = 1\nquality = \"draft\"\n\n[output]\ndir = \"out\"\n"
         "frames = [\"exr\", \"png\"]\nvideo = \"" +
         video + "\"\ncodec = \"" + codec + "\"\n\n" +
         "[camera]\nkeys = [\n  { t = 0.0, position = [0.0, 1.5, -4.0], target = [0.0, 0.6, 0.0], "
         "fov = 40.0 },\n  { t = 2.0, position = [3.0, 1.8, -2.5], target = [0.0, 0.7, 0.0], fov = "
         "45.0 },\n]\n\n[params]\nmorph_period = 2.0\n" +
         extra;
}

}  // namespace sdfreel::test
