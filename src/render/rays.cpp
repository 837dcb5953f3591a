#include "render/rays.h"

namespace sdfreel {

M8 RayPacket::valid() const {
  M8 m;
  for (int i = 0; i < LANES; ++i) m[i] = i < count ? -1 : 0;
  return m;
}

}  // namespace sdfreel
