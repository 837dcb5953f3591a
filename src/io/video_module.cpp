#include "io/video_module.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

#include "io/atomic_file.h"
#include "io/module_open.h"

namespace sdfreel {

const VideoModule& video_module() {
  static std::once_flag once;
  static const VideoModule* module = nullptr;
  static std::string problem;
  std::call_once(once, [] {
    open_module(
        SDFREEL_VIDEO_MODULE, "video",
        [](void* handle) {
          using Entry = const VideoModule* (*)();
          const auto entry = reinterpret_cast<Entry>(dlsym(handle, SDFREEL_VIDEO_MODULE_ENTRY));
          const VideoModule* found = entry ? entry() : nullptr;
          if (!found || found->abi != VIDEO_MODULE_ABI) return false;
          found->attach(VideoHost{&temp_path_for, &write_fully, &sync_and_close, &commit_temp_file,
                                  &discard_temp_file});
          module = found;
          return true;
        },
        problem);
  });
  if (!module) throw std::runtime_error(problem);
  return *module;
}

}  // namespace sdfreel
