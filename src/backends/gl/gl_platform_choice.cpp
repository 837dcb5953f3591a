#include "backends/gl/gl_platform_choice.h"

#include <cstdlib>

#include "backends/gl/egl_platform.h"
#include "backends/gl/osmesa_platform.h"

namespace sdfreel {

namespace {

std::string or_env(const std::string& given, const char* var, const char* fallback) {
  if (!given.empty()) return given;
  const char* env = std::getenv(var);
  return env && *env ? env : fallback;
}

}  // namespace

GlChoice resolved(const GlChoice& choice) {
  GlChoice c{or_env(choice.platform, "SDFREEL_GL_PLATFORM", "auto"),
             or_env(choice.device, "SDFREEL_GL_DEVICE", "software")};
  if (c.platform != "egl" && c.platform != "osmesa" && c.platform != "auto")
    throw GlPlatformError("unknown GL platform '" + c.platform + "': use egl, osmesa or auto");
  return c;
}

std::unique_ptr<GlPlatform> make_gl_platform(const GlChoice& choice) {
  const GlChoice c = resolved(choice);
  if (c.platform == "osmesa") {
    if (c.device != "software")
      throw GlPlatformError("OSMesa has only the software device, not '" + c.device +
                            "': use --gl-platform egl for a GPU");
    return std::make_unique<OsmesaPlatform>();
  }
  if (c.platform == "egl" || c.device != "software") return std::make_unique<EglPlatform>(c.device);
  try {
    return std::make_unique<EglPlatform>(c.device);
  } catch (const GlPlatformError& egl) {
    try {
      return std::make_unique<OsmesaPlatform>();
    } catch (const GlPlatformError& osmesa) {
      throw GlPlatformError(std::string("no GL platform starts: ") + egl.what() + "; " +
                            osmesa.what());
    }
  }
}

}  // namespace sdfreel
