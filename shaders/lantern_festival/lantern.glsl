// One lantern of seed 000 in its own frame: the twin of src/scenes/lantern_festival/lantern.h
// (paper, wood and metal parts; same shapes, sizes and order of operations).
#include "common/sdf.glsl"

// The in-place edits of the C++ (p -= ...) go through precise copies here.
float sdfPaper(vec3 p_in) {
  precise vec3 p = p_in - vec3(0.0, -1.0, 0.0);
  precise float box = sdBox(p - vec3(0.0, 4.0, 0.0), vec3(2.0));
  precise float cylinder = sdCappedCylinder(p - vec3(0.0, 1.5, 0.0), 1.5, 0.75);
  precise float cylinder_boundary = opOnion(cylinder, 0.03);
  return opSubtraction(box, cylinder_boundary);
}

float sdfWood(vec3 p_in) {
  precise vec3 p = p_in;
  p.y += 1.0;
  return sdBox(p, vec3(1.1, 0.04, 1.1));
}

// 0.75 * 0.707: the struts stand on the rings' diagonals.
const float STRUT_OFFSET = 0.75 * 0.707;

float sdfMetal(vec3 p_in) {
  precise vec3 p = p_in - vec3(0.0, -1.0, 0.0);
  precise float torus1 = sdTorus(p + vec3(0.0, -0.08, 0.0), vec2(0.75, 0.05));
  precise float torus2 = sdTorus(p + vec3(0.0, -2.0, 0.0), vec2(0.75, 0.05));
  precise float tori = opUnion(torus1, torus2);
  precise float cylindri = sdCappedCylinderOffset(opSymXZ(p + vec3(0.0, -1.0, 0.0)), 1.03, 0.05,
                                                  vec2(STRUT_OFFSET));
  return opSmoothUnion(cylindri, tori, 0.1);
}

float sdfLantern(vec3 p) {
  return opUnion(opUnion(sdfPaper(p), sdfWood(p)), sdfMetal(p));
}

// enum class LanternPart
const int PART_PAPER = 0;
const int PART_WOOD = 1;
const int PART_METAL = 2;

// The seed's material choice: metal or paper where strictly nearest, wood otherwise.
int nearestPart(vec3 p) {
  precise float dPaper = sdfPaper(p), dWood = sdfWood(p), dMetal = sdfMetal(p);
  if (dMetal < dPaper && dMetal < dWood) return PART_METAL;
  if (dPaper < dMetal && dPaper < dWood) return PART_PAPER;
  return PART_WOOD;
}
