// Adds one sample's colour and SDF evaluation count into the frame's sum targets: drawn once per
// sample, in sample order, with blend ONE + ONE into RGBA32F, so each channel gets one IEEE add a
// sample in the CPU backend's order (src/backends/osmesa/gl_plan_runner.h). Pixels that stopped
// sampling (u_live_mask 0, adaptive sampling) add nothing; sum_odd gets only odd list positions
// (u_odd 1) for the pixels' error estimates (adding 0 elsewhere keeps it exact). In packed rounds
// (common/sample_loop.glsl) a pixel's sample sits where u_live_slots says, not at the pixel.
uniform sampler2D u_colour;
uniform sampler2D u_sdf_evals;
uniform sampler2D u_live_mask;
uniform sampler2D u_live_slots;
uniform float u_odd;
uniform float u_packed;

layout(location = 0) out vec4 sum_colour;
layout(location = 1) out vec4 sum_sdf_evals;
layout(location = 2) out vec4 sum_odd;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (texelFetch(u_live_mask, p, 0).x == 0.0) discard;
  ivec2 q = u_packed != 0.0 ? ivec2(texelFetch(u_live_slots, p, 0).xy) : p;
  sum_colour = texelFetch(u_colour, q, 0);
  sum_sdf_evals = texelFetch(u_sdf_evals, q, 0);
  sum_odd = u_odd != 0.0 ? sum_colour : vec4(0.0);
}
