// One triangle that covers the viewport: vertices (-1,-1), (3,-1), (-1,3) from gl_VertexID, no
// vertex buffers. Used by every full-screen pass.
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
