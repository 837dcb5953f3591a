// Depth-only mesh passes (the sun's shadow map of the hall's casters, src/scenes/museum/
// sun_shadow.h): the rasteriser writes depth, the pass has no colour target.
void main() {}
