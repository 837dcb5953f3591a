// A tunnel lined with bricks: the classic polar deformation (the angle around the tunnel, 1/r
// along it), an image file on iChannel0 (textures/bricks.jpg, repeated and mipmapped, as
// Shadertoy's texture defaults), lit by a lamp that flickers down the tunnel.
// atan(y, x) from + - * / and a polynomial (error below 1e-5 radians): GLSL's own atan is the
// driver's, and llvmpipe's changed in its last bits between Mesa 22.3 and 25.0, which would give
// this example's golden frames one hash per Mesa release.
float angle(vec2 p) {
  vec2 q = abs(p);
  float t = min(q.x, q.y) / max(max(q.x, q.y), 1e-30);
  float t2 = t * t;
  float a = ((-0.0464964749 * t2 + 0.15931422) * t2 - 0.327622764) * t2 * t + t;
  if (q.y > q.x) a = 1.57079637 - a;
  if (p.x < 0.0) a = 3.14159274 - a;
  return p.y < 0.0 ? -a : a;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  float r = length(p);
  float a = angle(p);
  float depth = 0.5 / r;
  vec2 uv = vec2(3.0 * a / 3.14159265, depth + 0.4 * iTime);  // 6 texture widths around
  // The mip level from coordinates without atan's seam at -x (where a jumps by 2 pi), which would
  // otherwise pick the coarsest level along that line.
  vec2 seamless = vec2(3.0 * angle(vec2(abs(p.x), p.y)) / 3.14159265, uv.y);
  vec3 bricks = textureGrad(iChannel0, uv, dFdx(seamless), dFdy(seamless)).rgb;
  // Linear light (the channel decodes sRGB): the far end fades into the dark, a warm lamp moves.
  float lamp = 0.5 + 0.5 * sin(6.0 * depth - 4.0 * iTime);
  vec3 light = vec3(1.0, 0.85, 0.6) * (0.35 + 0.9 * lamp * lamp) * exp(-0.2 * depth);
  vec3 col = bricks * light + vec3(0.02, 0.025, 0.04) * (1.0 - r);
  fragColor = vec4(pow(clamp(col, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);  // display values
}
