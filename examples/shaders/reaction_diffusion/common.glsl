// Common: the Gray-Scott reaction-diffusion step both buffers run (Karl Sims's form). A buffer's
// texel holds the two chemicals' concentrations, a in .x and b in .y; each frame the field takes
// two steps, one in Buffer A and one in Buffer B.

const float kDiffuseA = 1.0, kDiffuseB = 0.5;
const float kFeed = 0.0545, kKill = 0.062;  // the "coral" region: fronts that grow and branch

// The field at pixel p, wrapping round the edges (a torus: no border effects).
vec2 field(sampler2D s, ivec2 p) {
  ivec2 size = textureSize(s, 0);
  return texelFetch(s, (p + size) % size, 0).xy;
}

// A hash of a cell, 0..1 (integer arithmetic: the same on every GPU).
float cell_hash(ivec2 c) {
  uint h = uint(c.x) * 1664525u ^ uint(c.y) * 22695477u;
  h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
  return float(h & 0xffffffu) / 16777216.0;
}

// The first frame: chemical a everywhere, b in one 6x6-pixel cell in fifty.
vec2 seeded(vec2 fragCoord) {
  return vec2(1.0, step(0.98, cell_hash(ivec2(fragCoord) / 6)));
}

vec2 gray_scott_step(sampler2D s, ivec2 p) {
  vec2 c = field(s, p);
  vec2 lap = -c;
  lap += 0.2 * (field(s, p + ivec2(1, 0)) + field(s, p - ivec2(1, 0)) + field(s, p + ivec2(0, 1)) +
                field(s, p - ivec2(0, 1)));
  lap += 0.05 * (field(s, p + ivec2(1, 1)) + field(s, p + ivec2(-1, 1)) +
                 field(s, p + ivec2(1, -1)) + field(s, p + ivec2(-1, -1)));
  float reaction = c.x * c.y * c.y;
  float a = c.x + kDiffuseA * lap.x - reaction + kFeed * (1.0 - c.x);
  float b = c.y + kDiffuseB * lap.y + reaction - (kKill + kFeed) * c.y;
  return clamp(vec2(a, b), 0.0, 1.0);
}
