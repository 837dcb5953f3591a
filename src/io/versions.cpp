#include "io/versions.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenEXR/OpenEXRConfig.h>
#include <png.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
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
          {"libavcodec", av_version_string(avcodec_version())},
          {"libavformat", av_version_string(avformat_version())},
          {"libswscale", av_version_string(swscale_version())}};
}

}  // namespace sdfreel
