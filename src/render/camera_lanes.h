#pragma once
// primary_ray_dir for eight image positions at once (src/sdf/lanes.h): each lane performs
// primary_ray_dir's operations in its order, so it gives the same bits, without eight calls.
#include "render/camera.h"
#include "render/rays.h"
#include "sdf/lanes.h"

namespace sdfreel {

inline V3x8 primary_ray_dirs(const CameraBasis& cam, F8 px, F8 py, int w, int h) {
  const F8 sx = (2.0f * px - float(w)) / float(h);
  const F8 sy = (float(h) - 2.0f * py) / float(h);
  const V3x8 d =
      cam.forward + cam.right * (sx * cam.tan_half_fov) + cam.up * (sy * cam.tan_half_fov);
  return d / dm::sqrt(vdot(d, d));
}

// The primary rays from the camera's origin through image positions (px[i], py[i]) of lanes
// 0 .. count - 1 (the caller repeats its last position in the lanes beyond), as one packet.
inline RayPacket primary_packet(const CameraBasis& cam, float pixel_angle, F8 px, F8 py, int count,
                                int w, int h) {
  RayPacket packet;
  packet.origin = cam.origin;
  packet.pixel_angle = pixel_angle;
  packet.count = count;
  packet.dir = primary_ray_dirs(cam, px, py, w, h);
  return packet;
}

}  // namespace sdfreel
