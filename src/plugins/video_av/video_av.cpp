#include "plugins/video_av/video_av.h"

#include <stdexcept>

extern "C" {
#include <libavutil/error.h>
}

namespace sdfreel {

std::string av_error_text(int ret) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(ret, buf, sizeof buf);
  return buf;
}

int av_check(int ret, const std::string& what) {
  if (ret < 0) throw std::runtime_error("video: " + what + ": " + av_error_text(ret));
  return ret;
}

}  // namespace sdfreel
