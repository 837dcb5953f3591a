// Writes texel (x, row) of u_source times u_scale to pixel (x, row), rows counted from the top.
uniform sampler2D u_source;
uniform float u_scale;
uniform int u_flip;  // 1: read GL's bottom-up rows (an off-screen target drawn by an earlier pass)
out vec4 frag;
void main() {
  int h = textureSize(u_source, 0).y;
  int row = h - 1 - int(gl_FragCoord.y);
  int src_row = u_flip == 1 ? int(gl_FragCoord.y) : row;
  frag = texelFetch(u_source, ivec2(int(gl_FragCoord.x), src_row), 0) * u_scale;
}
