// Adds one sample's colour and SDF evaluation count into the frame's sum targets: drawn once per
// sample, in sample order, with blend ONE + ONE into RGBA32F, so each channel gets one IEEE add a
// sample in the CPU backend's order (src/backends/osmesa/gl_plan_runner.h).
uniform sampler2D u_colour;
uniform sampler2D u_sdf_evals;

layout(location = 0) out vec4 sum_colour;
layout(location = 1) out vec4 sum_sdf_evals;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  sum_colour = texelFetch(u_colour, p, 0);
  sum_sdf_evals = texelFetch(u_sdf_evals, p, 0);
}
