#pragma once
// `sdfreel bench --whole-process`: every target rendered end to end by a fresh `sdfreel render`
// on every backend (bench/whole_process.h); prints the table and writes DIR/whole_process.csv.
#include <string>
#include <vector>

namespace sdfreel {

struct WholeProcessTarget {
  std::string label;
  std::string timeline_file;  // what the render reads
  std::string resolution;     // passed as --resolution when not empty
  int frames = 0;             // how many of `frames` the timeline has
  int width = 0, height = 0;  // as rendered
  std::string samples;        // as the table shows them
};

struct WholeProcessOptions {
  std::vector<std::string> backends;
  std::string frames;  // the --frames list
  int repetitions = 3;
  std::string out;
};

// Returns the exit status: 0, or 1 when no render could be timed.
int run_whole_process(const std::vector<WholeProcessTarget>& targets, const WholeProcessOptions& o);

}  // namespace sdfreel
