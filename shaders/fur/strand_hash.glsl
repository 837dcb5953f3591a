// The twin of src/scenes/fur/strand_hash.h: pcg2d of a UV cell, bit for bit.
const uint PCG_MULTIPLIER = 1664525u;
const uint PCG_INCREMENT = 1013904223u;

uvec2 pcg2d(uvec2 v) {
  v = v * PCG_MULTIPLIER + PCG_INCREMENT;
  v.x += v.y * PCG_MULTIPLIER;
  v.y += v.x * PCG_MULTIPLIER;
  v ^= v >> 16u;
  v.x += v.y * PCG_MULTIPLIER;
  v.y += v.x * PCG_MULTIPLIER;
  v ^= v >> 16u;
  return v;
}

float strand_random(ivec2 cell) {
  uvec2 h = pcg2d(uvec2(cell));
  return float(h.x >> 8u) * (1.0 / 16777216.0);
}
