// Chrome spheres floating in a landscape: a cubemap on iChannel0 (textures/sky_equirect.jpg, an
// equirect panorama sdfreel turns into six faces) is both the background and what the spheres
// reflect, up to three bounces between them. The camera is the timeline's ([camera] keys).

const int kSpheres = 3;

vec4 sphere(int i) {  // centre, radius
  float t = iTime + 2.1 * float(i);
  if (i == 0) return vec4(0.0, 0.9 + 0.15 * sin(t), 0.0, 0.9);
  if (i == 1) return vec4(1.7, 0.55 + 0.1 * sin(1.3 * t), 0.8, 0.5);
  return vec4(-1.5, 0.45 + 0.1 * sin(1.7 * t), 0.9, 0.4);
}

// dot() from + and *, held to that order: llvmpipe's built-in dot (and normalize, reflect) fuse
// differently across Mesa releases (26.1 gives other last bits than 22.3 and 25.0).
float dot3(vec3 a, vec3 b) {
  precise float r = a.x * b.x + a.y * b.y + a.z * b.z;
  return r;
}

// The nearest sphere along the ray (distance, index), or (-1, -1).
vec2 hit(vec3 ro, vec3 rd) {
  vec2 best = vec2(-1.0);
  for (int i = 0; i < kSpheres; ++i) {
    vec4 s = sphere(i);
    precise vec3 oc = ro - s.xyz;
    precise float b = dot3(oc, rd);
    precise float h = b * b - dot3(oc, oc) + s.w * s.w;
    if (h < 0.0) continue;
    precise float t = -b - sqrt(h);
    if (t > 1e-3 && (best.x < 0.0 || t < best.x)) best = vec2(t, float(i));
  }
  return best;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  precise vec3 ro = iCameraPosition;
  precise vec3 d = iCameraToWorld * vec3(p, iCameraFocal);
  precise vec3 rd = d / sqrt(dot3(d, d));
  vec3 tint = vec3(1.0);
  for (int bounce = 0; bounce < 3; ++bounce) {
    vec2 h = hit(ro, rd);
    if (h.x < 0.0) break;
    vec4 s = sphere(int(h.y));
    ro += h.x * rd;
    precise vec3 n = (ro - s.xyz) / s.w;
    precise float c = 1.0 - max(-dot3(n, rd), 0.0);
    precise float fresnel = 0.6 + 0.4 * (c * c) * (c * c) * c;
    tint *= vec3(0.95, 0.93, 0.9) * fresnel;  // chrome, a little warm
    rd = rd - 2.0 * dot3(n, rd) * n;  // reflect()
  }
  vec3 col = tint * texture(iChannel0, rd).rgb;  // linear light (the channel decodes sRGB)
  fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
}
