#include "io/image_write.h"

#include <OpenImageIO/filesystem.h>

#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"

namespace sdfreel {

void write_image_atomic(const std::string& path, const char* format, const OIIO::ImageSpec& spec,
                        OIIO::TypeDesc data_type, const void* data) {
  auto out = OIIO::ImageOutput::create(format);
  if (!out)
    throw std::runtime_error("cannot write " + path + ": OpenImageIO has no " + format +
                             " writer: " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw std::runtime_error("cannot write " + path + ": this OpenImageIO's " + format +
                             " writer cannot write to memory");
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  out->set_ioproxy(&memory);
  if (!(out->open(path, spec) && out->write_image(data_type, data) && out->close()))
    throw std::runtime_error("cannot write " + path + ": " + out->geterror());
  out.reset();
  write_file_atomic(path, bytes.data(), bytes.size());
}

}  // namespace sdfreel
