// [time], [camera] and [params]: everything that changes over video time.
#include <functional>
#include <optional>

#include "timeline/sections.h"
#include "timeline/suggest.h"

namespace sdfreel {
namespace {

// Called with each key value (or a constant) so that the caller can check its range.
using ValueCheck = std::function<void(const toml::node& at, const std::vector<double>& v,
                                      const std::string& name)>;

Interp read_interp(const TomlReader& r, const toml::table& t, const std::string& section,
                   Interp fallback) {
  const toml::node* n = t.get("interpolation");
  if (!n) return fallback;
  std::string name =
      r.choice(*n, section + ".interpolation", {"step", "linear", "smooth", "catmull-rom"});
  return *parse_interp(name);
}

// Key times must strictly increase: a curve is a function of t.
void check_after(const TomlReader& r, std::optional<double> previous, double t,
                 const toml::node& at, const std::string& name) {
  if (!previous || t > *previous) return;
  r.fail(at, name + ": t = " + format_number(t) + " is not after the previous key's t = " +
                 format_number(*previous) + " (key times must strictly increase)");
}

// A curve table: interpolation (optional) and keys = [[t, value], ...].
Curve read_curve(const TomlReader& r, const toml::table& t, const std::string& section,
                 Interp fallback, size_t components, const ValueCheck& check) {
  Curve c;
  c.interp = read_interp(r, t, section, fallback);
  const toml::node& keys_node = r.require(t, "keys", "[" + section + "]");
  const toml::array& keys = r.array(keys_node, section + ".keys");
  if (keys.empty()) r.fail(keys_node, section + ".keys needs at least one key");
  for (size_t i = 0; i < keys.size(); ++i) {
    const std::string name = section + ".keys[" + std::to_string(i) + "]";
    const toml::array* pair = keys.get(i)->as_array();
    if (!pair || pair->size() != 2) r.fail(*keys.get(i), name + " must be a [t, value] pair");
    const double at = r.number(*pair->get(0), name + " t");
    check_after(r, c.t.empty() ? std::nullopt : std::optional(c.t.back()), at, *pair->get(0), name);
    std::vector<double> v = r.numbers(*pair->get(1), name + " value", components);
    if (check) check(*pair->get(1), v, name + " value");
    c.t.push_back(at);
    c.values.push_back(std::move(v));
  }
  return c;
}

// One camera key: t, position and target required; fov and roll keep the previous key's, as in
// every animation tool (the first key: the scene's default fov and roll 0).
CameraKey read_camera_key(const TomlReader& r, const toml::node& node, const std::string& name,
                          const SceneInfo& scene, const CameraKey* previous) {
  const toml::table& t = r.table(node, name);
  r.check_keys(t, name, {"t", "position", "target", "fov", "roll"});
  CameraKey key;
  key.t = r.number(r.require(t, "t", name), name + ".t");
  key.pose.position = r.point(r.require(t, "position", name), name + ".position");
  const toml::node& target = r.require(t, "target", name);
  key.pose.target = r.point(target, name + ".target");
  key.pose.fov_deg = previous ? previous->pose.fov_deg : scene.default_camera.fov_deg;
  key.pose.roll_deg = previous ? previous->pose.roll_deg : 0.0;
  if (const toml::node* fov = t.get("fov")) {
    key.pose.fov_deg = r.number(*fov, name + ".fov");
    if (!(key.pose.fov_deg > 0.0 && key.pose.fov_deg < 180.0))
      r.fail(*fov,
             name + ".fov " + format_number(key.pose.fov_deg) + " is outside (0, 180) degrees");
  }
  if (const toml::node* roll = t.get("roll")) key.pose.roll_deg = r.number(*roll, name + ".roll");
  if (key.pose.position == key.pose.target)
    r.fail(target, name + ": position equals target, so the camera has no direction to look in");
  return key;
}

}  // namespace

void parse_time(const TomlReader& r, const toml::table& root, Timeline& tl) {
  const toml::node* n = root.get("time");
  if (!n) return;  // TIME = t
  const toml::table& time = r.table(*n, "time");
  r.check_keys(time, "[time]", {"interpolation", "keys"});
  tl.time = read_curve(r, time, "time", Interp::Linear, 1, nullptr);
}

void parse_camera(const TomlReader& r, const toml::table& root, const SceneInfo& scene,
                  Timeline& tl) {
  const toml::node* n = root.get("camera");
  if (!n) return;  // the scene's default camera
  const toml::table& camera = r.table(*n, "camera");
  r.check_keys(camera, "[camera]", {"interpolation", "speed", "keys"});
  tl.camera.interp = read_interp(r, camera, "camera", Interp::CatmullRom);
  if (const toml::node* speed = camera.get("speed"))
    tl.camera.constant_speed = r.choice(*speed, "camera.speed", {"keys", "constant"}) == "constant";
  const toml::node* keys_node = camera.get("keys");
  if (!keys_node) return;
  const toml::array& keys = r.array(*keys_node, "camera.keys");
  for (size_t i = 0; i < keys.size(); ++i) {
    const std::string name = "camera.keys[" + std::to_string(i) + "]";
    const auto& done = tl.camera.keys;
    CameraKey key =
        read_camera_key(r, *keys.get(i), name, scene, done.empty() ? nullptr : &done.back());
    check_after(r, done.empty() ? std::nullopt : std::optional(done.back().t), key.t,
                *keys.get(i)->as_table()->get("t"), name);
    tl.camera.keys.push_back(key);
  }
  tl.camera.prepare();  // curves and arc-length table once, not per frame
}

void parse_params(const TomlReader& r, const toml::table& root, const SceneInfo& scene,
                  Timeline& tl) {
  const toml::node* n = root.get("params");
  if (!n) return;
  const toml::table& params = r.table(*n, "params");
  std::vector<std::string> names;
  for (const ParamSpec& p : scene.params) names.push_back(p.name);

  for (const auto& [key, node] : keys_in_file_order(params)) {
    const std::string param(key->str());
    const ParamSpec* spec = find_param(scene.params, param);
    if (!spec)
      r.fail(key->source(), "unknown parameter '" + param + "' for scene '" + scene.name + "'" +
                                did_you_mean(param, names));

    const std::string path = "params." + param;
    auto in_range = [&](const toml::node& at, const std::vector<double>& v,
                        const std::string& name) {
      for (double x : v)
        if (x < spec->min || x > spec->max)
          r.fail(at, name + " " + format_number(x) + " is outside the range of " + param + ", " +
                         format_number(spec->min) + ".." + format_number(spec->max));
    };
    ParamTrack track{param, {}};
    if (const toml::table* animated = node->as_table()) {
      r.check_keys(*animated, "[" + path + "]", {"interpolation", "keys"});
      track.curve =
          read_curve(r, *animated, path, Interp::Linear, size_t(spec->components), in_range);
    } else {
      std::vector<double> v = r.numbers(*node, path, size_t(spec->components));
      in_range(*node, v, path);
      track.curve.t = {0.0};
      track.curve.values = {v};
    }
    tl.params.push_back(std::move(track));
  }
}

}  // namespace sdfreel
