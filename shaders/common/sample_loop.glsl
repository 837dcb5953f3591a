// main() of a scene's ray pass: the GLSL twin of the CPU ray pass (src/backends/cpu/
// cpu_ray_pass.cpp). Frame plans run once per sample offset and sum the samples afterwards in
// list order (src/backends/osmesa/gl_plan_runner.h), so this traces the one ray of this pixel for
// u_sample_offset. The scene file includes this and defines radiance().
#include "common/camera.glsl"

vec3 radiance(Ray ray, inout RayStats stats);

// `precise` keeps Mesa from reordering what feeds the output (and every local is precise too:
// see det_math.glsl for why both are needed).
//
// frag_color: linear radiance, alpha 1 (coverage). frag_sdf_evals.x: the ray's SDF evaluation
// count (the "sdf_evals" target), summed into RayStats by the backend.
layout(location = 0) precise out vec4 frag_color;
layout(location = 1) out vec4 frag_sdf_evals;

// Adaptive sampling: pixels that stopped (u_live_mask 0) trace nothing when the runner allows it
// (u_discard_stopped 1: a plan whose only pass is this one, so no other pass reads the pixel).
uniform sampler2D u_live_mask;
uniform float u_discard_stopped;
// Packed rounds (u_packed 1, such plans only): fragment k (row-major from GL's bottom row) traces
// the k-th live pixel, whose window position u_live_pixels holds at k (x < 0: none left). llvmpipe
// shades blocks of pixels in lanes, so packing keeps its lanes full as the CPU's packets are, where
// stopped pixels scattered over the frame would leave most lanes of most blocks discarded.
uniform sampler2D u_live_pixels;
uniform float u_packed;

void main() {
  ivec2 window = ivec2(gl_FragCoord.xy);
  if (u_packed != 0.0) {
    vec2 live = texelFetch(u_live_pixels, window, 0).xy;
    if (live.x < 0.0) discard;
    window = ivec2(live);
  } else if (u_discard_stopped != 0.0 && texelFetch(u_live_mask, window, 0).x == 0.0) {
    discard;
  }
  // GL's window origin is bottom-left; ImageRGBA's row 0 is the top row.
  int x = window.x;
  int y = u_resolution.y - 1 - window.y;
  RayStats stats = RayStats(0u, 0u, 0u);
  precise vec3 dir = primary_ray_dir(float(x) + u_sample_offset.x, float(y) + u_sample_offset.y);
  frag_color = vec4(radiance(Ray(u_camera_origin, dir, u_pixel_angle), stats), 1.0);
  frag_sdf_evals = vec4(float(stats.sdf_evals), 0.0, 0.0, 0.0);
}
