#pragma once
// Keyframed curves: step, linear, smooth (cubic Hermite, zero slopes at keys), catmull-rom
// (centripetal). Values are vectors of any fixed size; before the first key and after the last the
// curve holds its end value.
#include <optional>
#include <string>
#include <vector>

namespace sdfreel {

enum class Interp { Step, Linear, Smooth, CatmullRom };
std::optional<Interp> parse_interp(const std::string& name);
const char* interp_name(Interp interp);  // as the timeline spells it

struct Curve {
  Interp interp = Interp::Linear;
  std::vector<double> t;                    // strictly increasing
  std::vector<std::vector<double>> values;  // one vector per key, all the same size
  std::vector<double> sample(double at) const;
};

}  // namespace sdfreel
