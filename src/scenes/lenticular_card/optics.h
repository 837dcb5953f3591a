#pragma once
// The lenslets' optics (techniques.md, "Lenticular print"), shared by the card's shading and its
// tests. A lens of pitch p over a print at depth e (the sheet's thickness, about its focal
// length) focuses parallel rays onto one line of the print: seen at angle theta from the lens's
// normal (in the plane across the lenses, positive toward +x), the ray refracts to
// theta' = asin(sin(theta) / n) and meets the print at x = -e * tan(theta') from the lens centre.
// The print under lens k holds N strips (interlace.h): the strip seen is floor(N * (0.5 + x / p)),
// and past the lens's edge the neighbour's strips show, which restarts the views: the repeat
// (flip) zones.
#include <cstdint>

namespace sdfreel::lenticular_card {

// tan(theta') from sin(theta): s = sin(theta) / n, s / sqrt(1 - s^2). Finite for |sin| <= 1 and
// n >= 1 (no asin, no tan: the same float bits in GLSL).
float refracted_tan(float sin_theta, float ior);

// The print position seen through the lens whose centre is at lens coordinate `centre` (lens
// units: one lens = 1), for a sheet `thickness` lens pitches thick.
float seen_print_position(float centre, float sin_theta, float ior, float thickness);

// The view that N strips a lens show at sin(theta): N - 1 - (floor(N * (0.5 - e/p tan)) mod N).
int seen_view(float sin_theta, float ior, float thickness, int views);

// The viewing angle (degrees) of strip boundary `boundary` (0 at the lens centre, +-1, +-2 ...
// outward): where N * (0.5 - e tan(theta')) is integral, i.e. tan(theta') = boundary / (N e) and
// sin(theta) = n sin(atan(that)). Double and libm: the tests' independent prediction.
double switch_angle_deg(int boundary, int views, double ior, double thickness);

// The seed's billboard scrolling: the print holds for `hold` of each period, then slides up by
// one print height (smoothstep), then holds the other print. In print heights, in [0, 2); double
// so that TIME 1e6 keeps its phase.
double scroll_offset(double time, double period, double hold);

}  // namespace sdfreel::lenticular_card
