// rgb: a uniform colour; alpha: 1000 * row + column, rows counted from the top.
uniform vec4 u_colour;
uniform ivec2 u_resolution;
layout(location = 0) out vec4 frag;
void main() {
  float row = float(u_resolution.y - 1 - int(gl_FragCoord.y));
  frag = vec4(u_colour.rgb, row * 1000.0 + (gl_FragCoord.x - 0.5));
}
