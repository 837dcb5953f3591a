// Buffer B: a second step, from Buffer A's output of this frame.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor = vec4(gray_scott_step(iChannel0, ivec2(fragCoord)), 0.0, 1.0);
}
