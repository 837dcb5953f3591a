// main() of a ray pass that lays down depth (src/render/frame_plan.h, RayPass with a depth
// target): the shader defines shade_ray(), which returns false for a miss (discarded, nothing
// written, as RayPassOutput::keep) or the colour and the hit's view depth, written as window depth
// (src/render/camera_model.h) so the depth test composites it with meshes.
#include "common/camera.glsl"

bool shade_ray(Ray ray, inout RayStats stats, out vec3 colour, out float view_depth);

layout(location = 0) precise out vec4 frag_color;
layout(location = 1) out vec4 frag_sdf_evals;

void main() {
  int x = int(gl_FragCoord.x);
  int y = u_resolution.y - 1 - int(gl_FragCoord.y);
  RayStats stats = RayStats(0u, 0u, 0u);
  precise vec3 dir = primary_ray_dir(float(x) + u_sample_offset.x, float(y) + u_sample_offset.y);
  precise vec3 colour;
  precise float view_depth;
  if (!shade_ray(Ray(u_camera_origin, dir, u_pixel_angle), stats, colour, view_depth)) discard;
  gl_FragDepth = window_depth(view_depth);
  frag_color = vec4(colour, 1.0);
  frag_sdf_evals = vec4(float(stats.sdf_evals), 0.0, 0.0, 0.0);
}
