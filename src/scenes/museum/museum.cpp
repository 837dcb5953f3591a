// Scene "museum" (seed 004): a gallery hall drawn the conventional way (meshes, a depth buffer,
// a sun through the window) with the seed's exhibits in it. The frame is a plan of passes
// (render/frame_plan.h):
//   0. once a frame, before the samples: the sun's shadow map (museum/sun_shadow.h), the depth of
//      the window wall, plinths and bench (a mesh pass with the sun's view) and of exhibit 1
//      (ray-marched from the sun inside its bound);
//   1. sky: a ray pass into the "hall" target (what the window shows);
//   2. hall: one instanced cube mesh for every box of the hall (museum/hall_layout.h), lit by the
//      sun shadowed through the map, ambient and Blinn-Phong specular;
//   3. exhibits on their plinths (museum/exhibits.h): exhibit 1, the sdf_morph object ray-marched
//      inside its bounding mesh, composited by depth, reflecting a probe of the hall taken from its
//      centre in prepare() (museum/probe.h); exhibit 2, the lenticular card, on the second plinth
//      (museum/card_exhibit.h: the card's own ray pass, depth tested and written); exhibit 3, the
//      fur case, on the third (museum/fur_exhibit.h: its mesh passes, scaled onto the plinth);
//   4. exhibit 4, the air: occlusion from depth -> crepuscular rays -> composite with fog
//      (museum/atmosphere.h); its plinth, in the sun before the window, holds a lattice tower
//      whose bars cut the light into shafts (museum/lattice_tower.h, boxes of the hall).
//
// Parameters (besides sdf_morph's, which style exhibit 1: morph_period, rotation_speed, color,
// reflectivity, environment_intensity; its key light is the museum's sun):
//   fog_density      sigma of the distance fog, per metre
//   rays_strength    scale of the crepuscular rays added to the frame
//   exhibit_lift     exhibit 1 raised above its plinth top, metres
//   exhibit_shift_x  exhibit 1 moved along x (along the hall), metres
//   exhibit_shift_z  exhibit 1 moved along z (across the hall), metres
//   exhibit_yaw      exhibit 1 turned about the vertical, radians
//   exhibit_scale    exhibit 1's size (1 = sdf_morph's object, about 1 m tall)
#include <cstring>
#include <memory>
#include <mutex>
#include <vector>

#include "io/cache_file.h"
#include "render/camera_model.h"
#include "scenes/common/param.h"
#include "scenes/common/surface_output.h"
#include "scenes/fur/exhibit_params.h"
#include "scenes/museum/atmosphere.h"
#include "scenes/museum/card_exhibit.h"
#include "scenes/museum/exhibits.h"
#include "scenes/museum/fur_exhibit.h"
#include "scenes/museum/meshes.h"
#include "scenes/museum/sun_shadow.h"
#include "scenes/scene.h"

namespace sdfreel {

SceneInfo sdf_morph_scene_info();

namespace museum {
namespace {

constexpr const char* HALL_TARGET = "hall";
// MarchSettings::hit_mask (the bench's per-surface errors): the frame holds these ids instead,
// one per surface: exhibit 1 is sdf_morph's HIT_ID_OBJECT (1), the card and its stand 3 and 4
// (card_exhibit.h), the fur's shapes 5 to 7 (fur_exhibit.h).
constexpr float HIT_ID_SKY = 0.0f, HIT_ID_HALL = 2.0f;

std::vector<ParamSpec> params() {
  std::vector<ParamSpec> p = {
      scalar_param("fog_density", 0.02, 0.0, 0.5, "sigma of the distance fog, per metre"),
      scalar_param("rays_strength", 0.7, 0.0, 5.0, "scale of the crepuscular rays"),
      scalar_param("exhibit_lift", 0.0, -0.5, 3.0, "exhibit 1 raised above its plinth, metres"),
      scalar_param("exhibit_shift_x", 0.0, -4.0, 4.0, "exhibit 1 moved along the hall, metres"),
      scalar_param("exhibit_shift_z", 0.0, -4.0, 4.0, "exhibit 1 moved across the hall, metres"),
      scalar_param("exhibit_yaw", 0.0, -6.3, 6.3, "exhibit 1 turned about the vertical, radians"),
      scalar_param("exhibit_scale", 0.65, 0.05, 3.0, "exhibit 1's size (1 = sdf_morph's object)"),
  };
  for (const ParamSpec& s : sdf_morph_scene_info().params) p.push_back(s);
  for (const ParamSpec& s : fur::exhibit_param_specs(FUR_PARAM_PREFIX)) p.push_back(s);
  return p;
}

// The sky in the frame's mode: its colour, its id (hit_mask) or no surface (surface passes).
glm::vec3 sky_output(const glm::vec3& dir, bool ids, int surface) {
  if (surface != SURFACE_COLOUR) return noSurface(surface);
  return ids ? glm::vec3(HIT_ID_SKY) : sky(dir);
}

RayPass sky_pass(bool ids, int surface) {
  RayPass p;
  p.name = "sky";
  p.colour = HALL_TARGET;
  p.sdf_evals = "";
  p.shader = "museum/museum.glsl";
  p.uniforms = {{"u_hit_mask", 1, {ids ? 1.0f : 0.0f}}, {"u_surface", 1, {float(surface)}}};
  p.scalar = [ids, surface](const Ray& ray, glm::vec3& colour, float&, bool& keep, RayStats&) {
    colour = sky_output(ray.dir, ids, surface);
    keep = true;
  };
  p.packet = [ids, surface](const RayPacket& rays, RayPassOutput& out, RayStats&) {
    for (int i = 0; i < rays.count; ++i) {
      out.colour[i] = sky_output(rays.dir.lane(i), ids, surface);
      out.keep[i] = true;
    }
  };
  return p;
}

MeshPass hall_pass(const HallLight& light, bool ids, int surface) {
  MeshPass p;
  p.name = "hall";
  p.mesh = unit_cube();
  p.instances.clear();
  for (const HallBox& b : hall_boxes())
    p.instances.push_back(box_instance(b.lo, b.hi, glm::vec4(b.albedo, b.material)));
  p.colour = HALL_TARGET;
  p.fragment = "museum/hall.frag";
  p.uniforms = light_uniforms(light);
  p.uniforms.push_back({"u_hit_mask", 1, {ids ? 1.0f : 0.0f}});
  p.uniforms.push_back({"u_surface", 1, {float(surface)}});
  p.inputs = {{SUN_MAP_TARGET, SUN_MAP_SAMPLER}};
  // The map's windows, made by the first fragment that reads the map: the plan's setup passes
  // have drawn it by then, and every run of this plan draws the same map (a pure function of the
  // frame), so they hold for every sample.
  struct Windows {
    std::once_flag made;
    SunMapWindows windows;
  };
  auto windows = std::make_shared<Windows>();
  p.shade = [light, ids, surface, windows](const MeshFragment& f) {
    if (ids) return glm::vec4(glm::vec3(HIT_ID_HALL), 1.0f);
    if (surface != SURFACE_COLOUR)
      return glm::vec4(surfaceOutput(surface, glm::length(f.world_position - light.eye),
                                     glm::normalize(f.world_normal)),
                       1.0f);
    const ImageRGBA& image = (*f.inputs)[0];
    std::call_once(windows->made,
                   [&] { windows->windows = sun_map_windows(image, sun_view().size); });
    const SunMap map{&image, &sun_view(), &windows->windows};
    return glm::vec4(hall_radiance(f.world_position, f.world_normal, glm::vec3(f.instance_data),
                                   f.instance_data.w, light, map),
                     1.0f);
  };
  return p;
}

class MuseumScene : public Scene {
 public:
  void prepare(const FrameContext& ctx) override {
    // The probe is a pure function of its centre: made again only when exhibit 1 moves.
    const glm::vec3 centre = exhibit_one_centre(ctx);
    if (!probe_ || probe_->centre != centre)
      probe_ = std::make_shared<const ReflectionProbe>(
          render_probe(centre, hall_boxes(), HallLight{centre, sun_occluders()}));
    prints_ = &lenticular_card::default_card_prints();
  }
  std::vector<ShaderTexture> shader_textures() const override {
    std::vector<ShaderTexture> t = lenticular_card::card_shader_textures(*prints_);
    t.push_back(probe_texture(*probe_));
    return t;
  }
  // The probe is a pure function of its centre (the hall is fixed), the prints have their key.
  uint64_t shader_textures_key() const override {
    const glm::vec3 c = probe_->centre;
    const uint64_t words[4] = {prints_->key, uint64_t(bits(c.x)), uint64_t(bits(c.y)),
                               uint64_t(bits(c.z))};
    return checksum64(words, sizeof words) | 1ull;  // never 0 ("unknown")
  }
  glm::vec3 radiance(const Ray& ray, RayStats&) const override { return sky(ray.dir); }
  void prepare_solids(const FrameContext&) override {}  // the hall does not move
  std::optional<float> solid_distance(const glm::vec3& p) const override {
    return hall_distance(p);
  }
  FramePlan frame_plan(const FrameContext& ctx) const override {
    FramePlan plan;
    plan.near_plane = 0.05f;
    plan.far_plane = 60.0f;
    plan.targets.push_back({HALL_TARGET, TargetKind::Colour, glm::vec4(0.0f)});
    plan.targets.push_back(sun_map_target());
    plan.setup_passes.push_back(sun_casters_pass());
    const CameraModel cam =
        make_camera_model(ctx.camera, ctx.width, ctx.height, plan.near_plane, plan.far_plane);
    HallLight light{ctx.camera.origin, sun_occluders()};
    const bool ids = ctx.march.hit_mask;
    const int surface = ctx.march.surface;
    plan.passes.push_back(sky_pass(ids, surface));
    plan.passes.push_back(hall_pass(light, ids, surface));
    const ExhibitStage stage{ctx, cam, light, HALL_TARGET, DEPTH_TARGET, probe_.get()};
    ExhibitPasses extra[PLINTH_COUNT];
    extra[CARD_PLINTH] = card_exhibit(*prints_);
    extra[FUR_PLINTH] = fur_exhibit();
    add_exhibit_passes(plan, stage, extra);
    if (ids || surface != SURFACE_COLOUR) {  // ids, depths and normals: no air in front
      plan.passes.push_back(copy_pass(HALL_TARGET, COLOUR_TARGET));
      return plan;
    }
    Atmosphere air;
    air.fog_density = float(ctx.params.scalar("fog_density"));
    air.rays_strength = float(ctx.params.scalar("rays_strength"));
    add_atmosphere_passes(plan, air, ctx, cam, HALL_TARGET);
    return plan;
  }

 private:
  static uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
  }
  std::shared_ptr<const ReflectionProbe> probe_;
  const lenticular_card::CardPrints* prints_ = nullptr;
};

// Hard places: inside exhibit 1's bound, and the floor at a grazing angle.
std::vector<CameraPose> test_poses() {
  return {CameraPose{{-2.95, 1.55, -1.45}, {-3.0, 1.3, -1.75}, 60.0, 0.0},
          CameraPose{{5.5, 0.12, 3.0}, {-5.0, 0.0, -2.0}, 40.0, 0.0}};
}

}  // namespace
}  // namespace museum

SceneInfo museum_scene_info() {
  SceneInfo info;
  info.name = "museum";
  info.description =
      "A small gallery hall (seed 004) drawn as meshes with a depth buffer: floor, walls, "
      "ceiling, a tall window the low sun shines through, a door, a bench, four plinths, "
      "paintings of landscapes and labels. Exhibit 1 is the sdf_morph object, ray-marched inside "
      "its bounding box and composited with the hall by depth; exhibit 2 is the lenticular card "
      "(the scene "
      "lenticular_card's ray pass, depth tested against the hall); exhibit 3 is the fur case "
      "(the scene fur's shell-textured shapes, pushed and bouncing, as meshes); exhibit 4 is the "
      "light itself: crepuscular rays (GPU Gems 3, ch. 13) from the window's sky and a distance "
      "fog, with an open white lattice tower on the fourth plinth, in the sun before the window, "
      "whose bars cut the light into shafts.";
  info.params = museum::params();
  info.default_camera = CameraPose{{4.0, 1.6, 1.7}, {-3.5, 1.05, -1.6}, 55.0, 0.0};
  info.map_ceiling = museum::ROOM_H - 0.05;  // the map looks down from under the ceiling
  info.map_side_view = false;                // a wall
  info.test_poses = museum::test_poses();
  info.shader = "museum/museum.glsl";
  info.make = [] { return std::unique_ptr<Scene>(new museum::MuseumScene()); };
  info.draws_surfaces = true;
  return info;
}

}  // namespace sdfreel
