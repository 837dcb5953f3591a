#pragma once
// Starts the GL platform a GlChoice (gl_choice.h) names.
#include <memory>
#include <string>

#include "backends/gl/gl_choice.h"
#include "backends/gl/gl_platform.h"

namespace sdfreel {

// The choice with empty fields filled from the environment and the defaults; GlPlatformError for
// an unknown platform.
GlChoice resolved(const GlChoice& choice);

// Throws GlPlatformError with every reason when no platform of the choice starts.
std::unique_ptr<GlPlatform> make_gl_platform(const GlChoice& choice);

}  // namespace sdfreel
