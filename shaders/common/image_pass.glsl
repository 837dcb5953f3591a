// What an image pass's shader includes (src/render/frame_plan.h, ImagePass): pixel coordinates
// with row 0 at the top, as the CPU pixel functions have them, and reads of input targets there.
#include "common/frame.glsl"

layout(location = 0) precise out vec4 frag_out;

// This fragment's pixel, image coordinates (row 0 at the top).
ivec2 image_pixel() {
  return ivec2(int(gl_FragCoord.x), u_resolution.y - 1 - int(gl_FragCoord.y));
}

// Texel (x, y) of an input target, image coordinates; GL stores row 0 at the bottom.
vec4 read_image(sampler2D image, ivec2 p) {
  return texelFetch(image, ivec2(p.x, u_resolution.y - 1 - p.y), 0);
}
