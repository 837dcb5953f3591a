#pragma once
#include <map>
#include <string>

namespace sdfreel {

// Versions of the libraries that shape pixels or files (OIIO, OCIO, OpenEXR, libav), for the
// manifest: a hash mismatch after an upgrade is then explained by the manifest itself.
std::map<std::string, std::string> io_library_versions();

}  // namespace sdfreel
