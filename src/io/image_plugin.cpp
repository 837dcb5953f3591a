#include "io/image_plugin.h"

#include <dlfcn.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "io/image_plugin_abi.h"
#include "io/module_open.h"

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
    open_module(
        SDFREEL_IMAGE_MODULE, "image",
        [](void* handle) {
          module.read = reinterpret_cast<SdfreelImageReadFn>(dlsym(handle, SDFREEL_IMAGE_READ));
          module.free = reinterpret_cast<SdfreelImageFreeFn>(dlsym(handle, SDFREEL_IMAGE_FREE));
          module.write = reinterpret_cast<SdfreelImageWriteFn>(dlsym(handle, SDFREEL_IMAGE_WRITE));
          module.writes =
              reinterpret_cast<SdfreelImageWritesFn>(dlsym(handle, SDFREEL_IMAGE_WRITES));
          if (module.read && module.free && module.write && module.writes) return true;
          module = {};
          return false;
        },
        problem);
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
