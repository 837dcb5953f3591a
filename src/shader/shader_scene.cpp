#include "shader/shader_scene.h"

#include <limits>

#include "shader/glsl_text.h"
#include "shader/shadertoy_uniforms.h"
#include "timeline/timeline.h"

namespace sdfreel {

namespace {

void add_uniforms(const std::string& file, const std::string& source,
                  std::vector<ParamSpec>& params) {
  for (const DeclaredUniform& u : declared_uniforms(source)) {
    if (is_shadertoy_uniform(u.name))
      throw InputError(file, u.line, 0,
                       "uniform " + u.name +
                           " is declared by sdfreel already (docs/shaders.md): "
                           "remove this declaration");
    if (const ParamSpec* known = find_param(params, u.name)) {
      if (known->components != u.components)
        throw InputError(file, u.line, 0,
                         "uniform " + u.name + " is declared elsewhere with " +
                             std::to_string(known->components) + " components");
      continue;
    }
    ParamSpec p;
    p.name = u.name;
    p.components = u.components;
    p.def = u.init.empty() ? std::vector<double>(size_t(u.components), 0.0) : u.init;
    p.min = -std::numeric_limits<double>::max();
    p.max = std::numeric_limits<double>::max();
    p.doc = "uniform of the shader (" + file + ":" + std::to_string(u.line) + ")";
    params.push_back(std::move(p));
  }
}

}  // namespace

std::shared_ptr<const SceneInfo> make_shader_scene(std::shared_ptr<const ShaderProject> project,
                                                   const std::string& name) {
  auto info = std::make_shared<SceneInfo>();
  info->name = name;
  info->description = "a user's shader: " + project->path;
  // iMouse: Shadertoy's xy = position while pressed, zw = click position (negative: released).
  info->params.push_back({"iMouse", 4, {0, 0, 0, 0}, -1e9, 1e9, "Shadertoy's iMouse, in pixels"});
  if (!project->common_file.empty())
    add_uniforms(project->common_file, project->common_source, info->params);
  for (const ShaderPass& p : project->passes) add_uniforms(p.file, p.source, info->params);
  info->default_camera.position = {0.0, 1.0, 5.0};
  info->display_referred = project->display_referred;
  info->shader_project = std::move(project);
  return info;
}

}  // namespace sdfreel
