#pragma once
// Image files through OpenImageIO, published with every write checked: the image is encoded into
// memory, then written by write_file_atomic (unique temporary name, size check, fsync, rename).
// OIIO's own file writers do not all report a short write on a full disk.
#include <OpenImageIO/imageio.h>

#include <string>

namespace sdfreel {

// Encodes `data` (of `data_type`, laid out as `spec` says) with the named OIIO format plugin
// ("png", "openexr") and publishes it at `path`. Throws std::runtime_error naming `path`.
void write_image_atomic(const std::string& path, const char* format, const OIIO::ImageSpec& spec,
                        OIIO::TypeDesc data_type, const void* data);

}  // namespace sdfreel
