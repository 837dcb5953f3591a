// Water droplets on the pads and the petals: the twin of src/scenes/water_lily/droplets.h (the
// constants and dropletAt, the same operations).
const float DROP_CELL = 0.11;
const float DROP_MIN_R = 0.12;
const float DROP_MAX_R = 0.26;
const float DROP_SHARE_PAD = 0.45;
const float DROP_SHARE_PETAL = 0.22;
const float DROP_EDGE = 0.12;
const float DROP_MARGIN = 0.02;
const float DROP_UP0 = 0.45, DROP_UP1 = 0.75;
const uint DROP_SEED = 907u;
const float DROP_SLOPE = 1.4;
const float DROP_RING = 0.55, DROP_RING_DARK = 0.6;
const float DROP_CAUSTIC = 1.6;
const float DROP_SHININESS = 256.0, DROP_SPECULAR = 1.5;

struct Droplet {
  float cover;
  vec2 offset;
};

Droplet dropletAt(vec2 xz, uint seed, float share, float up) {
  Droplet drop = Droplet(0.0, vec2(0.0));
  precise float face = dm_smoothstep(DROP_UP0, DROP_UP1, up);
  if (!(face > 0.0)) return drop;
  precise float fx = floor(xz.x / DROP_CELL), fz = floor(xz.y / DROP_CELL);
  uint h = hash2i(int(fx), int(fz), seed);
  if (!(hash_to_unit(h) < share)) return drop;
  uint hx = pcg_hash(h), hz = pcg_hash(hx), hr = pcg_hash(hz);
  precise float radius = DROP_MIN_R + (DROP_MAX_R - DROP_MIN_R) * hash_to_unit(hr);
  precise float inset = radius + DROP_MARGIN, span = 1.0 - 2.0 * inset;
  precise float cx = fx + inset + span * hash_to_unit(hx);
  precise float cz = fz + inset + span * hash_to_unit(hz);
  drop.offset = vec2((xz.x / DROP_CELL - cx) / radius, (xz.y / DROP_CELL - cz) / radius);
  precise float d = sqrt(drop.offset.x * drop.offset.x + drop.offset.y * drop.offset.y);
  drop.cover = face * (1.0 - dm_smoothstep(1.0 - DROP_EDGE, 1.0, d));
  return drop;
}
