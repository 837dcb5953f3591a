#include "io/versions.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenEXR/OpenEXRConfig.h>
#include <png.h>

// The versions sdfreel was built against (its video module links them, io/video_module.h):
// asking the libraries would load them at every start.
extern "C" {
#include <libavcodec/version.h>
#include <libavformat/version.h>
#include <libswscale/version.h>
}

namespace sdfreel {

namespace {

std::string av_version_string(unsigned v) {
  return std::to_string(v >> 16) + "." + std::to_string((v >> 8) & 0xff) + "." +
         std::to_string(v & 0xff);
}

}  // namespace

std::map<std::string, std::string> io_library_versions() {
  return {{"libpng", PNG_LIBPNG_VER_STRING},
          {"opencolorio", OCIO_NAMESPACE::GetVersion()},
          {"openexr", OPENEXR_VERSION_STRING},
          {"libavcodec", av_version_string(LIBAVCODEC_VERSION_INT)},
          {"libavformat", av_version_string(LIBAVFORMAT_VERSION_INT)},
          {"libswscale", av_version_string(LIBSWSCALE_VERSION_INT)}};
}

}  // namespace sdfreel
