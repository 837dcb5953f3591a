#pragma once
// The host's functions the module calls (io/video_module.h's VideoHost), set by attach().
#include "io/video_module.h"

namespace sdfreel {

void attach_host(const VideoHost& host);

}  // namespace sdfreel
