// Image: the concentration of b as ink on paper, lit from the top left by its own gradient.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 texel = 1.0 / iResolution.xy;
  vec2 uv = fragCoord * texel;
  float b = texture(iChannel0, uv).y;
  float dx = texture(iChannel0, uv + vec2(texel.x, 0.0)).y - texture(iChannel0, uv - vec2(texel.x, 0.0)).y;
  float dy = texture(iChannel0, uv + vec2(0.0, texel.y)).y - texture(iChannel0, uv - vec2(0.0, texel.y)).y;
  vec3 paper = vec3(0.95, 0.92, 0.85), ink = vec3(0.08, 0.16, 0.32);
  vec3 col = mix(paper, ink, smoothstep(0.1, 0.35, b));
  col += 0.6 * vec3(dx - dy);  // a relief: lit from the top left
  fragColor = vec4(clamp(col, 0.0, 1.0), 1.0);
}
