#include "shader/shadertoy_uniforms.h"

namespace sdfreel {

const std::vector<ShadertoyUniform>& shadertoy_uniforms() {
  static const std::vector<ShadertoyUniform> all = {{"vec3", "iResolution"},
                                                    {"float", "iTime"},
                                                    {"float", "iTimeDelta"},
                                                    {"int", "iFrame"},
                                                    {"float", "iFrameRate"},
                                                    {"float", "iChannelTime", true},
                                                    {"vec3", "iChannelResolution", true},
                                                    {"vec4", "iMouse"},
                                                    {"vec4", "iDate"},
                                                    {"float", "iSampleRate"},
                                                    {"sampler2D", "iChannel0"},
                                                    {"sampler2D", "iChannel1"},
                                                    {"sampler2D", "iChannel2"},
                                                    {"sampler2D", "iChannel3"},
                                                    {"vec3", "iCameraPosition"},
                                                    {"vec3", "iCameraTarget"},
                                                    {"vec3", "iCameraUp"},
                                                    {"float", "iCameraFov"},
                                                    {"float", "iCameraFocal"},
                                                    {"mat3", "iCameraToWorld"}};
  return all;
}

bool is_shadertoy_uniform(const std::string& name) {
  for (const ShadertoyUniform& u : shadertoy_uniforms())
    if (name == u.name) return true;
  return false;
}

}  // namespace sdfreel
