#pragma once
// What a render writes, checked against this machine's libraries before anything is written:
// the frame formats beyond EXR and PNG against OpenImageIO's writers, the video's codec against
// libav's encoders (the timeline library links neither).
#include "timeline/timeline.h"

namespace sdfreel {

// Why frame files of this extension (no dot; not exr or png) cannot be written here: the image
// module is missing, or OpenImageIO has no writer for it; "" when they can. Loads the module.
std::string unwritable_frame_format(const std::string& ext);
// Throws InputError at the name's place in the timeline for an extension no writer takes. Loads
// the image module only when the timeline names such a format.
void validate_frame_formats(const Timeline& tl);
// Throws InputError when a video is to be made and libav has no encoder for its codec.
void validate_video_encoder(const Timeline& tl, bool makes_video);

}  // namespace sdfreel
