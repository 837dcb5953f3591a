#pragma once
// Exhibit 1: the sdf_morph object ray-marched in object space inside its bounding mesh (seed 004,
// "How it works"). The bound is a box drawn with front faces culled, so its back faces cover the
// object on screen even with the camera inside the box; each fragment marches the camera's ray in
// the object's space (through the inverse model matrix) with sdf_morph's distance function, shades
// the hit with sdf_morph's shading under the museum's sun (shadowed through the sun's map, the
// pass's input), reflecting itself (the mirror ray marched through the object again, as sdf_morph
// traces its reflection) or else the hall's probe (copied into the pass), and writes the hit's own
// depth, so the depth test against the hall (late, on the marched depth) hides it and it hides the
// hall.
// The GLSL twin is shaders/museum/sdf_exhibit.frag.
#include <glm/glm.hpp>
#include <string>

#include "render/camera_model.h"
#include "render/frame_context.h"
#include "render/frame_plan.h"
#include "scenes/museum/lighting.h"
#include "scenes/museum/probe.h"
#include "scenes/sdf_morph/uniforms.h"

namespace sdfreel::museum {

// `model` maps exhibit space (origin at the centre of the plinth top, +Y up, metres) to the world;
// rotation, translation and uniform scale only.
MeshPass sdf_exhibit_pass(const glm::mat4& model, const sdf_morph::MorphUniforms& morph,
                          const HallLight& light, const ReflectionProbe& probe,
                          const FrameContext& ctx, const CameraModel& cam,
                          const std::string& colour, const std::string& depth);

// Exhibit 1 in the sun's shadow map (museum/sun_shadow.h): the bound drawn with the sun's view,
// each fragment marching the sun's ray through the object and writing the hit's depth in the map.
// The GLSL twin is shaders/museum/sdf_exhibit_shadow.frag.
MeshPass sdf_exhibit_shadow_pass(const glm::mat4& model, const sdf_morph::MorphUniforms& morph);

}  // namespace sdfreel::museum
