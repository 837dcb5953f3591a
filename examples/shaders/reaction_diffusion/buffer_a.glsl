// Buffer A: one step from Buffer B's last output (the previous frame's); the seeds at frame 0.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  if (iFrame == 0) {
    fragColor = vec4(seeded(fragCoord), 0.0, 1.0);
    return;
  }
  fragColor = vec4(gray_scott_step(iChannel0, ivec2(fragCoord)), 0.0, 1.0);
}
