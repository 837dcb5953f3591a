#include "options.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace sdfreel::mesh_bench {
namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

constexpr const char* USAGE =
    "usage: mesh_method_bench [--runs N] [--threads N] [--quality low|medium] "
    "[--cases hall,fur,museum] [--sizes 320x180,1280x720] [--spp 1,2,4] [--images DIR]";

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "mesh_method_bench: %s\n%s\n", why.c_str(), USAGE);
  std::exit(2);
}

}  // namespace

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s\n", USAGE);
      std::exit(0);
    }
    if (i + 1 >= argc) usage("missing value after " + a);
    const std::string v = argv[++i];
    if (a == "--runs") {
      o.runs = std::max(1, std::atoi(v.c_str()));
    } else if (a == "--threads") {
      o.threads = std::max(0, std::atoi(v.c_str()));
    } else if (a == "--quality") {
      if (v != "low" && v != "medium") usage("--quality is low or medium");
      o.quality = v == "low" ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM;
    } else if (a == "--images") {
      o.images = v;
    } else if (a == "--cases") {
      o.cases = split(v);
    } else if (a == "--sizes") {
      o.sizes.clear();
      for (const std::string& s : split(v)) {
        int w = 0, h = 0;
        if (std::sscanf(s.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1) usage("bad size " + s);
        o.sizes.push_back({w, h});
      }
    } else if (a == "--spp") {
      o.spp.clear();
      for (const std::string& s : split(v)) o.spp.push_back(std::max(1, std::atoi(s.c_str())));
    } else {
      usage("unknown option " + a);
    }
  }
  return o;
}

CaseSpec find_spec(const std::string& name) {
  for (const CaseSpec& s : standard_cases())
    if (s.name == name) return s;
  usage("unknown case " + name);
}

}  // namespace sdfreel::mesh_bench
