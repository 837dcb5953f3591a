#pragma once
// Compositing passes ([output] passes, docs/timeline.md#compositing-passes): images beside the
// beauty that an EXR frame carries as float channels of their own, named as Nuke and Blender read
// them. Which a scene gives: scenes/scene_passes.h.
#include <string>
#include <vector>

namespace sdfreel {

struct CompositingPass {
  std::string name;                   // as [output] passes names it
  std::vector<std::string> channels;  // its EXR channels, in order
  std::string meaning;                // one line, for docs and errors
};

// Every pass this build knows, in the documented order.
const std::vector<CompositingPass>& compositing_passes();
// The pass of that name, or null.
const CompositingPass* find_compositing_pass(const std::string& name);

// A pass of one frame: its channels' values, a pixel's channels together, rows top-down.
struct PassImage {
  std::string name;
  std::vector<std::string> channels;
  int width = 0, height = 0;
  std::vector<float> values;
};

}  // namespace sdfreel
