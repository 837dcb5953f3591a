#pragma once
// The frame formats a timeline names beyond EXR and PNG, checked against OpenImageIO's writers
// before anything is written (the timeline library does not link OpenImageIO).
#include "timeline/timeline.h"

namespace sdfreel {

// Throws InputError at the name's place in the timeline for an extension no writer takes. Loads
// the image module only when the timeline names such a format.
void validate_frame_formats(const Timeline& tl);

}  // namespace sdfreel
