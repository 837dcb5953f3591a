// The depth and normal passes' frame: what a scene shows instead of a colour when
// MarchSettings::surface asks. Twin of src/scenes/common/surface_output.h.
const int SURFACE_COLOUR = 0;
const int SURFACE_DISTANCE = 1;
const int SURFACE_NORMAL = 2;
const float NO_SURFACE_DISTANCE = 1e10;

vec3 surfaceOutput(int mode, float t, vec3 n) {
  return mode == SURFACE_DISTANCE ? vec3(t) : n;
}

vec3 noSurface(int mode) {
  return vec3(mode == SURFACE_DISTANCE ? NO_SURFACE_DISTANCE : 0.0);
}
