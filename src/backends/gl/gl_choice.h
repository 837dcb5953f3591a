#pragma once
// Which platform and device the GL backend runs on, as the options and the environment say.
// platform: egl, osmesa or auto (EGL where it starts, else OSMesa: both are Mesa's llvmpipe with
// the same bits). device (EGL only): software (the default), gpu or an index from
// `sdfreel devices`; a device other than software is never replaced by another one, nor by
// OSMesa. Empty fields take SDFREEL_GL_PLATFORM and SDFREEL_GL_DEVICE, then the defaults
// (gl_platform_choice.h). Plain data: the command line includes it without GL headers.
#include <string>

namespace sdfreel {

struct GlChoice {
  std::string platform;  // egl | osmesa | auto
  std::string device;    // software | gpu | N
  int threads = 0;       // CPU threads of sdfreel's own work between draws (0: automatic)
};

}  // namespace sdfreel
