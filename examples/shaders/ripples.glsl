// Ripples: a 2D Shadertoy-style Image shader, as a user would paste it from the site.
// Three drifting sources send out rings; where their waves meet they interfere, and the height
// of the summed wave picks a colour from a cosine palette (Inigo Quilez's). Only Shadertoy's
// own inputs are used: iResolution, iTime and fragCoord.

vec3 palette(float t) {
  return 0.5 + 0.5 * cos(6.28318 * (vec3(1.0, 1.0, 1.0) * t + vec3(0.0, 0.10, 0.20)));
}

// One source: rings moving outwards, fading with distance.
float wave(vec2 p, vec2 source, float phase) {
  float d = length(p - source);
  return sin(18.0 * d - 4.0 * iTime + phase) / (1.0 + 6.0 * d);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  // Centred, height from -1 to 1, square pixels.
  vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
  float t = 0.4 * iTime;
  float h = wave(p, vec2(0.8 * cos(t), 0.5 * sin(1.3 * t)), 0.0) +
            wave(p, vec2(-0.7 * cos(0.7 * t), 0.4 * cos(t)), 2.0) +
            wave(p, vec2(0.3 * sin(0.9 * t), -0.6 * cos(0.5 * t)), 4.0);
  vec3 col = palette(0.45 + 0.45 * h);
  col *= 0.35 + 0.65 * smoothstep(-0.6, 0.6, h);  // troughs darker, crests bright
  col *= 1.0 - 0.25 * dot(p, p) / 3.0;            // a soft vignette
  fragColor = vec4(col, 1.0);
}
