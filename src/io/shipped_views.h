#pragma once
// The shipped config's views (ocio/config.ocio, display "sRGB") evaluated by sdfreel's own
// deterministic math instead of OpenColorIO's CPU processor, whose rounding changes between OCIO
// releases (2.5 moved 7% of the 16-bit values of a frame by one unit against 2.1 and 2.4). So
// the display pixels of `config = "builtin"` are a function of the linear pixels and this build
// alone. OpenColorIO stays the authority: it names the config's displays and views when a timeline
// asks for another, it computes every other config's views, and tests/io/shipped_views_test.cpp
// holds these to its result within a stated tolerance on whatever version is installed (and the
// shipped file's displays and views to this list).
#include <cstddef>
#include <glm/vec3.hpp>
#include <string>

namespace sdfreel {

// Scene-linear Rec.709 -> display RGB (sRGB encoded, not yet clamped).
using ShippedView = glm::vec3 (*)(const glm::vec3& linear_rec709);

// The view's function, or nullptr when (display, view) is not one of the shipped views.
ShippedView shipped_view(const std::string& display, const std::string& view);

// The same view over n RGBA pixels in place (alpha kept), eight at a time in lanes: the same bits
// as shipped_view's function on each pixel, several times faster.
using ShippedViewPixels = void (*)(float* rgba, size_t n);
ShippedViewPixels shipped_view_pixels(const std::string& display, const std::string& view);

glm::vec3 aces_sdr_video_view(const glm::vec3& linear_rec709);  // "ACES 1.0 - SDR Video"
glm::vec3 untonemapped_view(const glm::vec3& linear_rec709);    // "Un-tone-mapped"

// The sRGB display encoding as OpenColorIO's "DISPLAY - CIE-XYZ-D65_to_sRGB" writes it (a
// monitor curve with gamma 2.4 and offset 0.055, whose linear segment meets the power segment in
// value and slope).
float srgb_encode_moncurve(float linear);

}  // namespace sdfreel
