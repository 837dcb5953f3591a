// What every frame hands a scene's shader: the GLSL face of FrameContext (src/render/
// frame_context.h), set by the OSMesa backend from the same struct the CPU backend reads
// (src/backends/osmesa/frame_uniforms.cpp). Scene parameters arrive as p_<name> (float or vec3),
// and each scene's shader_uniforms() adds its own per-frame constants.
#include "common/det_math.glsl"

#ifndef SDFREEL_MAX_SAMPLES
#define SDFREEL_MAX_SAMPLES 1024
#endif

// src/render/quality.h
struct MarchSettings {
  int max_steps;
  float hit_eps;
  float step_factor;
  float normal_eps;
  int shadow_steps;
  int reflect_steps;
  float max_dist;
};

// src/scenes/scene.h
struct Ray {
  vec3 origin;
  vec3 dir;
  float pixel_angle;
};

struct RayStats {
  uint sdf_evals;
  uint steps;
  uint capped;
};

uniform ivec2 u_resolution;  // width, height in pixels
uniform int u_frame;         // frame index
uniform float u_time;        // TIME as a float: coarse at 1e6 s, so scenes use wrapped phases
uniform vec3 u_camera_origin;
uniform vec3 u_camera_right;
uniform vec3 u_camera_up;
uniform vec3 u_camera_forward;
uniform float u_tan_half_fov;
uniform float u_pixel_angle;  // footprint_angle() of src/render/quality.h, as the CPU backend has it
uniform MarchSettings u_march;
uniform int u_sample_count;
uniform float u_inv_samples;  // 1 / sample count, computed on the host like the CPU backend
uniform vec2 u_sample_offsets[SDFREEL_MAX_SAMPLES];
// Frame plans run once per sample (src/render/frame_plan.h): this pass's sample offset, and the
// camera model of src/render/camera_model.h with the projection moved by that offset.
uniform vec2 u_sample_offset;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_near_plane;
uniform float u_depth_scale;  // far / (far - near)
