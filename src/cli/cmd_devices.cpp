// `sdfreel devices [--json]`: the GL devices this machine offers, with what --gl-device takes to
// choose each, and whether the OSMesa platform starts. Each EGL device is opened once to read the
// renderer and GL version its context reports, so a device that cannot render says why here.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands_impl.h"

#ifdef SDFREEL_HAVE_GL
#include "backends/gl/egl_devices.h"
#include "backends/gl/egl_platform.h"
#include "backends/gl/osmesa_platform.h"
#endif

namespace sdfreel {

namespace {

using nlohmann::json;

#ifdef SDFREEL_HAVE_GL
// The renderer and GL version of a context on `platform`, or the reason none starts.
json open_context(const std::function<std::unique_ptr<GlPlatform>()>& make) {
  try {
    std::unique_ptr<GlPlatform> p = make();
    json j = {{"renderer", p->gl().string(GL_RENDERER)},
              {"gl_version", p->gl().string(GL_VERSION)}};
    p->release();
    return j;
  } catch (const std::exception& e) {
    return {{"error", e.what()}};
  }
}

json egl_report() {
  json report = {{"devices", json::array()}};
  try {
    const EglLibrary& egl = egl_library();
    for (const EglDevice& d : egl_devices(egl)) {
      json j = {{"index", d.index},          {"name", d.name},
                {"vendor", d.vendor},        {"software", d.software},
                {"drm_node", d.drm_node},    {"render_node", d.render_node},
                {"cuda_index", d.cuda_index}};
      j["context"] = open_context([&] {
        return std::make_unique<EglPlatform>(d.software ? "software" : std::to_string(d.index));
      });
      report["devices"].push_back(j);
    }
    if (report["devices"].empty()) {
      // No device enumeration: the surfaceless platform still gives the software device.
      report["surfaceless"] =
          open_context([] { return std::make_unique<EglPlatform>("software"); });
    }
  } catch (const std::exception& e) {
    report["error"] = e.what();
  }
  return report;
}
#endif

json devices_report() {
#ifdef SDFREEL_HAVE_GL
  return {{"egl", egl_report()},
          {"osmesa", open_context([] { return std::make_unique<OsmesaPlatform>(); })}};
#else
  return {{"error", "this sdfreel was built without the GL backend"}};
#endif
}

std::string or_dash(const json& j, const char* key) {
  if (!j.contains(key)) return "-";
  if (j[key].is_number()) return j[key].get<int>() < 0 ? "-" : std::to_string(j[key].get<int>());
  const std::string s = j[key].get<std::string>();
  return s.empty() ? "-" : s;
}

void print_context(const json& c) {
  if (c.contains("error")) {
    std::printf("  cannot render: %s\n", c["error"].get<std::string>().c_str());
    return;
  }
  std::printf("  renderer:    %s\n  GL version:  %s\n", or_dash(c, "renderer").c_str(),
              or_dash(c, "gl_version").c_str());
}

bool starts(const json& c) {
  return !c.contains("error");
}

// Whether any GL platform renders here: the exit status is 0 when one does, else 1.
bool any_renders(const json& r) {
  if (r.contains("error")) return false;
  bool any = starts(r["osmesa"]);
  for (const json& d : r["egl"]["devices"]) any = any || starts(d["context"]);
  if (r["egl"].contains("surfaceless")) any = any || starts(r["egl"]["surfaceless"]);
  return any;
}

void print_report(const json& r) {
  if (r.contains("error")) {
    std::printf("%s\n", r["error"].get<std::string>().c_str());
    return;
  }
  const json& egl = r["egl"];
  if (egl.contains("error")) std::printf("EGL: %s\n", egl["error"].get<std::string>().c_str());
  for (const json& d : egl["devices"]) {
    const std::string choose = d["software"] ? "software" : std::to_string(d["index"].get<int>());
    std::printf("EGL device %d: %s (--gl-device %s)\n", d["index"].get<int>(),
                or_dash(d, "name").c_str(), choose.c_str());
    std::printf(
        "  vendor:      %s\n  software:    %s\n  DRM node:    %s\n  render node: %s\n"
        "  CUDA index:  %s\n",
        or_dash(d, "vendor").c_str(), d["software"] ? "yes" : "no", or_dash(d, "drm_node").c_str(),
        or_dash(d, "render_node").c_str(), or_dash(d, "cuda_index").c_str());
    print_context(d["context"]);
  }
  if (egl.contains("surfaceless")) {
    std::printf(
        "EGL (no device enumeration): Mesa's surfaceless platform (--gl-device software)\n");
    print_context(egl["surfaceless"]);
  }
  std::printf("OSMesa (--gl-platform osmesa, software only):\n");
  print_context(r["osmesa"]);
}

}  // namespace

void add_devices_command(CLI::App& app, int& status) {
  auto as_json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("devices", "list the GL devices and platforms that render");
  cmd->add_flag("--json", *as_json, "print the list as JSON");
  cmd->callback([as_json, &status] {
    const json r = devices_report();
    if (*as_json)
      std::printf("%s\n", r.dump(2).c_str());
    else
      print_report(r);
    status = any_renders(r) ? 0 : 1;
  });
}

}  // namespace sdfreel
