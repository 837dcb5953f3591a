// A strip of a frame and its compositing passes for the docs (docs/passes.png): the display frame,
// then depth (nearer brighter, as 1 / Z), normal (each component mapped from -1..1 to 0..1) and id
// (a colour per id) of the EXR that carries them ([output] passes = ["depth", "normal", "id"]):
//   cmake --build build --target pass_strip && build/pass_strip out/frames/00000 strip.png
// reads out/frames/00000.png and out/frames/00000.exr.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "io/exr_file.h"
#include "io/frame_files.h"

int main(int argc, char** argv) {
  using namespace sdfreel;
  if (argc != 3) {
    std::fprintf(stderr, "usage: pass_strip FRAME_WITHOUT_EXTENSION OUT.png\n");
    return 2;
  }
  const std::string frame = argv[1];
  try {
    const ImageRGB16 beauty = read_png16(frame + ".png");
    const std::string exr = frame + ".exr";
    const std::vector<float> z = read_exr_channel(exr, "Z"), id = read_exr_channel(exr, "id");
    const std::vector<float> n[3] = {read_exr_channel(exr, "N.X"), read_exr_channel(exr, "N.Y"),
                                     read_exr_channel(exr, "N.Z")};
    const int w = beauty.width, h = beauty.height;
    float nearest = 1e30f;
    for (float v : z) nearest = std::min(nearest, v);
    // Ids 1, 2, 3... as distinct hues; 0 (no surface) black.
    const float palette[8][3] = {{0, 0, 0},          {0.9f, 0.3f, 0.2f}, {0.2f, 0.7f, 0.3f},
                                 {0.2f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f}, {0.7f, 0.3f, 0.8f},
                                 {0.2f, 0.8f, 0.8f}, {0.9f, 0.6f, 0.3f}};
    ImageRGB16 out;
    out.width = 4 * w;
    out.height = h;
    out.pixels.assign(size_t(out.width) * h * 3, 0);
    auto put = [&](int panel, int x, int y, int c, float v) {
      out.pixels[(size_t(y) * out.width + size_t(panel) * w + x) * 3 + c] =
          uint16_t(std::clamp(v, 0.0f, 1.0f) * 65535.0f + 0.5f);
    };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        const bool none = n[0][i] == 0.0f && n[1][i] == 0.0f && n[2][i] == 0.0f;
        for (int c = 0; c < 3; ++c) {
          out.pixels[(size_t(y) * out.width + x) * 3 + c] = beauty.pixels[i * 3 + c];
          put(1, x, y, c, z[i] >= 1e10f ? 0.0f : nearest / z[i]);
          put(2, x, y, c, none ? 0.0f : n[c][i] * 0.5f + 0.5f);
          put(3, x, y, c, palette[int(id[i]) % 8][c]);
        }
      }
    write_png16_atomic(argv[2], out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pass_strip: %s\n", e.what());
    return 1;
  }
  return 0;
}
