#include "scenes/scene_reference.h"

#include <cstdio>

#include "scenes/scene_passes.h"

namespace sdfreel {

namespace {

std::string format(const char* fmt, double a, double b) {
  char buf[96];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

std::string joined(const std::vector<std::string>& items, const std::string& before,
                   const std::string& after) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + before + items[i] + after;
  return s;
}

std::string camera_values(const CameraPose& c) {
  return "position = " + format_param_values({c.position.x, c.position.y, c.position.z}) +
         ", target = " + format_param_values({c.target.x, c.target.y, c.target.z}) +
         ", fov = " + format_param_values({c.fov_deg});
}

// A Markdown table cell: a '|' in the text would end the cell.
std::string cell(const std::string& text) {
  std::string s;
  for (const char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
  return s;
}

}  // namespace

std::string format_param_values(const std::vector<double>& values) {
  std::string s;
  char b[32];
  for (size_t i = 0; i < values.size(); ++i) {
    std::snprintf(b, sizeof b, "%g", values[i]);
    s += (i ? ", " : "") + std::string(b);
  }
  return values.size() > 1 ? "[" + s + "]" : s;
}

std::string scene_reference_text(const SceneInfo& s) {
  std::string out = s.name + "\n  " + s.description + "\n\n";
  out += "default camera: " + camera_values(s.default_camera) + "\n";
  out += "compositing passes ([output] passes): " + joined(scene_passes(s), "", "") + "\n\n";
  char line[512];
  std::snprintf(line, sizeof line, "%-24s %-20s %-18s %s\n", "parameter", "default", "range",
                "meaning");
  out += line;
  for (const ParamSpec& p : s.params) {
    std::snprintf(line, sizeof line, "%-24s %-20s %-18s ", p.name.c_str(),
                  format_param_values(p.def).c_str(), format("%g .. %g", p.min, p.max).c_str());
    out += line + p.doc + "\n";
  }
  return out;
}

std::string scene_reference_markdown(const SceneInfo& s) {
  std::string out = "<!-- begin: sdfreel scenes " + s.name + " --markdown -->\n";
  out += "Default camera: `" + camera_values(s.default_camera) + "`.\n";
  out += "Compositing passes (`[output] passes`): " + joined(scene_passes(s), "`", "`") + ".\n\n";
  out += "| parameter | default | range | meaning |\n| --- | --- | --- | --- |\n";
  for (const ParamSpec& p : s.params)
    out += "| `" + p.name + "` | " + format_param_values(p.def) + " | " +
           format("%g .. %g", p.min, p.max) + " | " + cell(p.doc) + " |\n";
  out += "<!-- end: sdfreel scenes " + s.name + " --markdown -->\n";
  return out;
}

}  // namespace sdfreel
