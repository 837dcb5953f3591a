#include "shader/channel_images.h"

#include <stdexcept>

#include "shader/texture_file.h"
#include "timeline/timeline.h"

namespace sdfreel {

void load_channel_images(ShaderProject& project) {
  for (ShaderPass& pass : project.passes) {
    for (size_t c = 0; c < pass.channels.size(); ++c) {
      ChannelBinding& b = pass.channels[c];
      if (b.kind != ChannelKind::Texture && b.kind != ChannelKind::Cubemap) continue;
      const std::string where = std::string(pass_name(pass.kind)) + " iChannel" + std::to_string(c);
      const std::string file = b.origin_file.empty() ? pass.file : b.origin_file;
      std::vector<ImageRGBA> images;
      for (const std::string& f : b.files) {
        try {
          images.push_back(read_texture_file(f, b.srgb));
        } catch (const InputError& e) {
          throw InputError(file, b.origin_line, b.origin_column,
                           where + ": " + f + ": " + e.what());
        }
      }
      if (b.kind == ChannelKind::Texture) {
        b.image = std::make_shared<const ImageRGBA>(std::move(images.at(0)));
        continue;
      }
      try {
        if (images.size() == 1) {
          b.cube = std::make_shared<const CubeFaces>(cube_from_image(images[0]));
        } else {
          std::array<ImageRGBA, 6> faces;
          std::move(images.begin(), images.begin() + 6, faces.begin());
          b.cube = std::make_shared<const CubeFaces>(cube_from_faces(std::move(faces), b.files));
        }
      } catch (const std::runtime_error& e) {
        throw InputError(file, b.origin_line, b.origin_column,
                         where + ": cubemap " + b.files.at(0) + ": " + e.what());
      }
    }
  }
}

}  // namespace sdfreel
