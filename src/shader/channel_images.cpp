#include "shader/channel_images.h"

#include "shader/texture_file.h"
#include "timeline/timeline.h"

namespace sdfreel {

void load_channel_images(ShaderProject& project) {
  for (ShaderPass& pass : project.passes) {
    for (size_t c = 0; c < pass.channels.size(); ++c) {
      ChannelBinding& b = pass.channels[c];
      if (b.kind != ChannelKind::Texture) continue;
      try {
        b.image = std::make_shared<const ImageRGBA>(read_texture_file(b.files.at(0), b.srgb));
      } catch (const InputError& e) {
        const std::string file = b.origin_file.empty() ? pass.file : b.origin_file;
        throw InputError(file, b.origin_line, b.origin_column,
                         std::string(pass_name(pass.kind)) + " iChannel" + std::to_string(c) +
                             ": " + b.files.at(0) + ": " + e.what());
      }
    }
  }
}

}  // namespace sdfreel
