#include "io/module_open.h"

#include <dlfcn.h>

#include "render/data_files.h"

namespace sdfreel {

bool open_module(const std::string& file, const std::string& what,
                 const std::function<bool(void* handle)>& accept, std::string& problem) {
  std::string tried;
  problem.clear();
  for (const auto& path : module_file_candidates(file)) {
    tried += (tried.empty() ? "" : ", ") + path.string();
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      if (const char* e = dlerror(); e && std::string(e).find("No such file") == std::string::npos)
        problem = "cannot open sdfreel's " + what + " module: " + e;
      continue;
    }
    if (accept(handle)) return true;
    problem = path.string() + " is not sdfreel's " + what + " module of this version";
  }
  if (problem.empty())
    problem = "sdfreel's " + what + " module " + file + " is not installed (tried " + tried +
              "); reinstall sdfreel";
  return false;
}

}  // namespace sdfreel
