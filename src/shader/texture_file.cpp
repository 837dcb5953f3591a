#include "shader/texture_file.h"

#include <filesystem>

#include "io/exr_file.h"
#include "io/png_file.h"
#include "timeline/timeline.h"

namespace sdfreel {

ImageRGBA read_texture_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  try {
    if (ext == ".exr") return read_exr_file(path);
    if (ext != ".png")
      throw InputError(path, 0, 0,
                       "a texture is a .png or .exr file in this build (other formats: convert "
                       "them, e.g. `convert in.jpg out.png`)");
    const PngPixels png = read_png(path, 3);
    ImageRGBA image(png.width, png.height);
    for (size_t i = 0; i < size_t(png.width) * size_t(png.height); ++i) {
      for (size_t c = 0; c < 3; ++c) image.pixels[4 * i + c] = png.samples[3 * i + c] / 65535.0f;
      image.pixels[4 * i + 3] = 1.0f;
    }
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, 0, 0, std::string("cannot decode the texture: ") + e.what());
  }
}

}  // namespace sdfreel
