#include "pipeline/pass_images.h"

#include <algorithm>
#include <stdexcept>

namespace sdfreel {

void record_passes(const std::vector<std::string>& names, Backend& backend) {
  backend.record_sdf_evals(std::find(names.begin(), names.end(), "sdf_evals") != names.end());
}

std::vector<PassImage> pass_images(const std::vector<std::string>& names, const Backend& backend,
                                   int width, int height) {
  std::vector<PassImage> out;
  const size_t pixels = size_t(width) * height;
  for (const std::string& name : names) {
    const CompositingPass* pass = find_compositing_pass(name);
    if (!pass) throw std::logic_error("unknown compositing pass '" + name + "'");
    PassImage img{name, pass->channels, width, height, {}};
    if (name == "samples") {
      const SampleCounts& counts = backend.sample_counts();
      img.values.assign(counts.begin(), counts.end());
    } else if (name == "sdf_evals") {
      img.values = backend.sdf_eval_counts();
    }
    if (img.values.size() != pixels * pass->channels.size())
      throw std::logic_error("the " + backend.name() + " backend kept no '" + name +
                             "' pass of this frame");
    out.push_back(std::move(img));
  }
  return out;
}

}  // namespace sdfreel
