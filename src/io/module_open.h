#pragma once
// sdfreel's modules (lib/sdfreel/*.so: OpenImageIO's images, libav's encoders) are opened on first
// use so that their libraries never slow a start that does not need them. This finds and opens
// one, kept for the life of the process (those libraries do not unload cleanly).
#include <functional>
#include <string>

namespace sdfreel {

// Tries render/data_files.h's candidates for `file` in order; the first that dlopen opens and
// `accept` takes (given the handle, it looks up the module's entry points) is the module. Returns
// false with `problem` naming what went wrong, for the user: `what` names the module ("image").
bool open_module(const std::string& file, const std::string& what,
                 const std::function<bool(void* handle)>& accept, std::string& problem);

}  // namespace sdfreel
