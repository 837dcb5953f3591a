// Twisted box: a ray marcher written as a Shadertoy Image tab that flies the timeline's camera.
// sdfreel hands it the [camera] of the timeline (iCameraPosition, iCameraToWorld, iCameraFocal)
// and two parameters of its own, declared below as uniforms and animated in the timeline's
// [params]: how far the box twists and how round it is (docs/shaders.md).

uniform float twist = 1.0;      // radians of twist per unit of height
uniform float roundness = 0.1;  // the box's edge radius

// A rounded box of half-size b, twisted about the y axis.
float twisted_box(vec3 p) {
  float a = twist * p.y;
  p.xz = mat2(cos(a), -sin(a), sin(a), cos(a)) * p.xz;
  vec3 b = vec3(0.45, 0.9, 0.45) - roundness;
  vec3 q = abs(p) - b;
  // A twist stretches space: 0.7 keeps the march from overshooting for twists up to about 2.
  return 0.7 * (length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - roundness);
}

float scene(vec3 p, out int id) {
  float box = twisted_box(p - vec3(0.0, 1.0, 0.0));
  float floor_ = p.y;
  id = box < floor_ ? 1 : 0;
  return min(box, floor_);
}

float scene(vec3 p) {
  int id;
  return scene(p, id);
}

vec3 normal_at(vec3 p) {
  const vec2 e = vec2(1e-3, 0.0);
  return normalize(vec3(scene(p + e.xyy) - scene(p - e.xyy), scene(p + e.yxy) - scene(p - e.yxy),
                        scene(p + e.yyx) - scene(p - e.yyx)));
}

// Soft shadow towards the light (Inigo Quilez's penumbra estimate).
float soft_shadow(vec3 p, vec3 l) {
  float k = 1.0, t = 0.02;
  for (int i = 0; i < 64 && t < 8.0; ++i) {
    float h = scene(p + l * t);
    k = min(k, 10.0 * h / t);
    if (k < 1e-3) break;
    t += clamp(h, 0.01, 0.3);
  }
  return clamp(k, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  vec3 ro = iCameraPosition;
  vec3 rd = normalize(iCameraToWorld * vec3(uv, iCameraFocal));
  vec3 sky = mix(vec3(0.75, 0.82, 0.92), vec3(0.32, 0.48, 0.75), clamp(rd.y * 2.0, 0.0, 1.0));
  vec3 col = sky;
  float t = 0.0;
  int id = 0;
  for (int i = 0; i < 160 && t < 40.0; ++i) {
    float d = scene(ro + rd * t, id);
    if (d < 1e-3 * t) break;
    t += d;
  }
  if (t < 40.0) {
    vec3 p = ro + rd * t, n = normal_at(p);
    vec3 light = normalize(vec3(-0.5, 0.8, -0.4));
    vec3 albedo = id == 1 ? vec3(0.8, 0.25, 0.1)
                          : vec3(0.55) + 0.2 * mod(floor(p.x) + floor(p.z), 2.0);
    float diffuse = max(dot(n, light), 0.0) * soft_shadow(p + n * 2e-3, light);
    float ambient = 0.5 + 0.5 * n.y;
    col = albedo * (1.6 * diffuse * vec3(1.0, 0.95, 0.85) + 0.35 * ambient * vec3(0.6, 0.7, 0.9));
    col = mix(col, sky, 1.0 - exp(-0.002 * t * t));  // haze in the distance
  }
  col = 1.0 - exp(-1.1 * col);      // tone map
  col = pow(col, vec3(1.0 / 2.2));  // to display values, which is what a shader writes
  fragColor = vec4(col, 1.0);
}
