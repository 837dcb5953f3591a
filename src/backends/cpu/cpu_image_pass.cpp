#include "backends/cpu/cpu_image_pass.h"

#include <stdexcept>

#include "render/tiling.h"

namespace sdfreel {

void run_image_pass(const ImagePass& pass, const CpuPassContext& pc, CpuTargets& targets) {
  if (!pass.pixel) throw std::runtime_error("image pass '" + pass.name + "' has no CPU code");
  ImageInputs in;
  for (const ImageInput& i : pass.inputs) {
    if (i.target == pass.output)
      throw std::runtime_error("image pass '" + pass.name + "' reads its own output '" +
                               pass.output + "'");
    in.images.push_back(&targets.get(i.target, pass.name));
  }
  ImageRGBA& out = targets.get(pass.output, pass.name);
  if (pass.rows) {
    const ImagePass::RowFunction row = pass.rows(in);
    for_each_tile(out.width, out.height, pc.tile_size, pc.threads, [&](const Tile& t) {
      for (int y = t.y0; y < t.y1; ++y) row(y, t.x0, t.x1, out.at(t.x0, y));
    });
    return;
  }
  for_each_tile(out.width, out.height, pc.tile_size, pc.threads, [&](const Tile& t) {
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) {
        const glm::vec4 v = pass.pixel(in, x, y);
        float* p = out.at(x, y);
        p[0] = v.x;
        p[1] = v.y;
        p[2] = v.z;
        p[3] = v.w;
      }
  });
}

}  // namespace sdfreel
