#pragma once
// The one way scenes declare a parameter (SceneInfo::params): its name, default, inclusive range
// and one line on its meaning and unit, written where it is declared (docs/adding-a-scene.md).
#include <utility>
#include <vector>

#include "render/params.h"

namespace sdfreel {

inline ParamSpec scalar_param(const char* name, double def, double min, double max,
                              const char* doc) {
  return ParamSpec{name, 1, {def}, min, max, doc};
}

// A linear Rec.709 colour, each channel in [0, 1].
inline ParamSpec colour_param(const char* name, std::vector<double> def, const char* doc) {
  return ParamSpec{name, 3, std::move(def), 0.0, 1.0, doc};
}

}  // namespace sdfreel
