#pragma once
// Reads the image files a shader's channels bind, when the timeline is loaded: a file that is
// missing or cannot be decoded stops the render before anything is written, and `check` reports
// it. OpenImageIO is opened only here, and only for a shader that has image channels.
#include "shader/shader_project.h"

namespace sdfreel {

// Fills each Texture binding's `image` and each Cubemap binding's `cube`. Throws InputError naming
// the file that binds the channel, the pass, the channel and the image file.
void load_channel_images(ShaderProject& project);

}  // namespace sdfreel
