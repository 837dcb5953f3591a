#include "io/image_plugin.h"

#include <dlfcn.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "io/image_plugin_abi.h"
#include "render/data_files.h"

namespace sdfreel {

namespace {

struct ImageModule {
  SdfreelImageReadFn read = nullptr;
  SdfreelImageFreeFn free = nullptr;
  SdfreelImageWriteFn write = nullptr;
  SdfreelImageWritesFn writes = nullptr;
};

// Opened once and kept for the life of the process (OIIO's libraries do not unload cleanly).
const ImageModule& image_module() {
  static std::once_flag once;
  static ImageModule module;
  static std::string problem;
  std::call_once(once, [] {
    std::string tried;
    for (const auto& path : module_file_candidates(SDFREEL_IMAGE_MODULE)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        if (const char* e = dlerror();
            e && std::string(e).find("No such file") == std::string::npos)
          problem = std::string("cannot open sdfreel's image module: ") + e;
        continue;
      }
      module.read = reinterpret_cast<SdfreelImageReadFn>(dlsym(handle, SDFREEL_IMAGE_READ));
      module.free = reinterpret_cast<SdfreelImageFreeFn>(dlsym(handle, SDFREEL_IMAGE_FREE));
      module.write = reinterpret_cast<SdfreelImageWriteFn>(dlsym(handle, SDFREEL_IMAGE_WRITE));
      module.writes = reinterpret_cast<SdfreelImageWritesFn>(dlsym(handle, SDFREEL_IMAGE_WRITES));
      if (module.read && module.free && module.write && module.writes) return;
      module = {};
      problem = path.string() + " is not sdfreel's image module of this version";
    }
    if (problem.empty())
      problem = "sdfreel's image module " SDFREEL_IMAGE_MODULE " is not installed (tried " + tried +
                "); reinstall sdfreel";
  });
  if (!module.read) throw std::runtime_error(problem);
  return module;
}

template <typename T>
void widen(const void* samples, size_t count, std::vector<float>& out) {
  const T* s = static_cast<const T*>(samples);
  out.assign(s, s + count);
}

}  // namespace

StoredImage read_stored_image(const std::string& path) {
  const ImageModule& module = image_module();
  SdfreelStoredImage raw{};
  char error[1024] = "";
  if (!module.read(path.c_str(), &raw, error, sizeof error))
    throw std::runtime_error(error[0] ? error : "unreadable");
  std::unique_ptr<SdfreelStoredImage, SdfreelImageFreeFn> owned(&raw, module.free);
  StoredImage image;
  image.width = raw.width;
  image.height = raw.height;
  image.channels = raw.channels;
  image.bits = raw.bits;
  const size_t count = size_t(raw.width) * size_t(raw.height) * size_t(raw.channels);
  if (raw.bits == 8)
    widen<uint8_t>(raw.samples, count, image.samples);
  else if (raw.bits == 16)
    widen<uint16_t>(raw.samples, count, image.samples);
  else
    widen<float>(raw.samples, count, image.samples);
  return image;
}

void write_image_file(const std::string& format_name, const std::string& path,
                      const ImageToWrite& image) {
  const ImageModule& module = image_module();
  const SdfreelImageToWrite raw{
      format_name.c_str(), path.c_str(),  image.width,     image.height,  image.channels,
      image.sample_bits,   image.samples, image.file_bits, image.quality, "sdfreel"};
  char error[1024] = "";
  if (!module.write(&raw, error, sizeof error))
    throw std::runtime_error(error[0] ? error : "OpenImageIO could not write it");
}

bool image_module_writes(const std::string& extension) {
  return image_module().writes(extension.c_str()) != 0;
}

}  // namespace sdfreel
