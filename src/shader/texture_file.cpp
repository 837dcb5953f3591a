#include "shader/texture_file.h"

#include <array>

#include "render/srgb.h"
#include "timeline/timeline.h"

namespace sdfreel {

ImageRGBA texture_texels(const StoredImage& stored, bool srgb) {
  const bool integer = stored.bits == 8 || stored.bits == 16;
  // Division, not multiplication by 1/255: code / 255 is the float nearest the exact value.
  const float scale = stored.bits == 8 ? 255.0f : stored.bits == 16 ? 65535.0f : 1.0f;
  const bool decode = srgb && integer;
  const int n = stored.channels;
  // Every code's decoded value once (the same srgb_to_linear), instead of a pow per texel.
  std::vector<float> decoded;
  if (decode)
    for (int code = 0; code <= int(scale); ++code)
      decoded.push_back(srgb_to_linear(float(code) / scale));
  ImageRGBA image(stored.width, stored.height);
  for (size_t i = 0; i < size_t(stored.width) * size_t(stored.height); ++i) {
    const float* s = &stored.samples[i * size_t(n)];
    // 1: gray; 2: gray and alpha; 3: RGB; 4: RGBA.
    const std::array<float, 4> v =
        n >= 3   ? std::array<float, 4>{s[0], s[1], s[2], n == 4 ? s[3] : scale}
        : n == 2 ? std::array<float, 4>{s[0], s[0], s[0], s[1]}
                 : std::array<float, 4>{s[0], s[0], s[0], scale};
    float* out = &image.pixels[4 * i];
    for (size_t c = 0; c < 4; ++c) {
      out[c] = decode && c < 3 ? decoded[size_t(v[c])] : integer ? v[c] / scale : v[c];
    }
  }
  return image;
}

ImageRGBA read_texture_file(const std::string& path, bool srgb) {
  try {
    return texture_texels(read_stored_image(path), srgb);
  } catch (const std::exception& e) {
    throw InputError(path, 0, 0, std::string("cannot read the image: ") + e.what());
  }
}

}  // namespace sdfreel
