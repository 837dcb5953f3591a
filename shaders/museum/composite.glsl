// The hall fogged plus the crepuscular rays: the twin of composite() in
// src/scenes/museum/atmosphere.cpp.
#include "common/image_pass.glsl"
#include "common/camera.glsl"
#include "museum/lighting.glsl"

const vec3 FOG_AMBIENT = vec3(0.10, 0.105, 0.11);
const vec3 FOG_SUN = vec3(0.9, 0.8, 0.65);
const vec3 SHAFT_COLOUR = vec3(1.0, 0.9, 0.75);
const float FOG_MAX_DISTANCE = 16.0;

uniform sampler2D u_scene;
uniform sampler2D u_rays_image;
uniform sampler2D u_depth;
uniform float u_fog_density;
uniform float u_rays_strength;

void main() {
  ivec2 p = image_pixel();
  precise vec3 hall = read_image(u_scene, p).rgb;
  precise float rays = read_image(u_rays_image, p).x;
  precise float z = read_image(u_depth, p).x;
  precise float vd = u_near_plane / (1.0 - z / u_depth_scale);
  precise float d = z >= 1.0 ? FOG_MAX_DISTANCE : dm_min(vd, FOG_MAX_DISTANCE);
  precise float s = u_fog_density * d;
  precise float fog = 1.0 - 1.0 / (1.0 + s + 0.5 * s * s);
  precise vec3 dir = primary_ray_dir(float(p.x) + 0.5, float(p.y) + 0.5);
  precise float lobe = dm_max(dm_dot(dir, TO_SUN), 0.0);
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  lobe = lobe * lobe;
  precise vec3 fog_colour = FOG_AMBIENT + FOG_SUN * lobe;
  frag_out = vec4(hall * (1.0 - fog) + fog_colour * fog + SHAFT_COLOUR * (rays * u_rays_strength),
                  1.0);
}
