#include "io/video_module.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

#include "io/atomic_file.h"
#include "render/data_files.h"

namespace sdfreel {

const VideoModule& video_module() {
  static std::once_flag once;
  static const VideoModule* module = nullptr;
  static std::string problem;
  std::call_once(once, [] {
    std::string tried;
    for (const auto& path : module_file_candidates(SDFREEL_VIDEO_MODULE)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      // Kept open for the process: libav's libraries do not unload cleanly.
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        if (const char* e = dlerror();
            e && std::string(e).find("No such file") == std::string::npos)
          problem = std::string("cannot open sdfreel's video module: ") + e;
        continue;
      }
      using Entry = const VideoModule* (*)();
      const auto entry = reinterpret_cast<Entry>(dlsym(handle, SDFREEL_VIDEO_MODULE_ENTRY));
      const VideoModule* found = entry ? entry() : nullptr;
      if (found && found->abi == VIDEO_MODULE_ABI) {
        found->attach(VideoHost{&temp_path_for, &write_fully, &sync_and_close, &commit_temp_file,
                                &discard_temp_file});
        module = found;
        return;
      }
      problem = path.string() + " is not sdfreel's video module of this version";
    }
    if (problem.empty())
      problem = "sdfreel's video module " SDFREEL_VIDEO_MODULE " is not installed (tried " + tried +
                "); reinstall sdfreel";
  });
  if (!module) throw std::runtime_error(problem);
  return *module;
}

}  // namespace sdfreel
