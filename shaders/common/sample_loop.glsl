// main() of a ray-marched scene's full-screen pass: the twin of CpuBackend::render's pixel loop
// (src/backends/cpu/cpu_backend.cpp). Samples are summed in list order and the sum is multiplied
// by 1 / count, exactly as there, so the two backends add the same numbers in the same order.
// The scene file includes this and defines radiance().
#include "common/camera.glsl"

vec3 radiance(Ray ray, inout RayStats stats);

// `precise` keeps Mesa from reordering what feeds the output (and every local is precise too:
// see det_math.glsl for why both are needed).
//
// rgb: linear radiance. alpha: the pixel's SDF evaluation count; the backend moves it into
// RayStats and writes alpha = 1, as the CPU backend does.
layout(location = 0) precise out vec4 frag_color;

void main() {
  // GL's window origin is bottom-left; ImageRGBA's row 0 is the top row.
  int x = int(gl_FragCoord.x);
  int y = u_resolution.y - 1 - int(gl_FragCoord.y);
  RayStats stats = RayStats(0u, 0u, 0u);
  precise vec3 sum = vec3(0.0);
  for (int i = 0; i < u_sample_count; ++i) {
    precise vec2 o = u_sample_offsets[i];
    precise vec3 dir = primary_ray_dir(float(x) + o.x, float(y) + o.y);
    sum += radiance(Ray(u_camera_origin, dir, u_pixel_angle), stats);
  }
  frag_color = vec4(sum * u_inv_samples, float(stats.sdf_evals));
}
