#pragma once
// The command line of mesh_method_bench.
#include <embree3/rtcore.h>

#include <string>
#include <utility>
#include <vector>

#include "bench_case.h"

namespace sdfreel::mesh_bench {

struct Options {
  int runs = 5, threads = 1;
  RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM;
  std::vector<std::string> cases{"hall", "fur", "museum"};
  std::vector<std::pair<int, int>> sizes{{320, 180}, {1280, 720}};
  std::vector<int> spp{1, 2, 4};
  std::string images;  // a folder: write id and difference pictures of every case measured
};

// Exits with status 2 and the usage on a bad option (0 for --help).
Options parse_options(int argc, char** argv);
// The standard case named `name`, or exit 2.
CaseSpec find_spec(const std::string& name);

}  // namespace sdfreel::mesh_bench
