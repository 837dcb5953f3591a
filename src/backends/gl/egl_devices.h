#pragma once
// The devices EGL sees (EGL_EXT_device_enumeration), and the choice of one: `software` (Mesa's
// llvmpipe, EGL_MESA_device_software: the default, whose frames match the goldens), `gpu` (the
// first device that is not software) or an index from `sdfreel devices`.
#include <string>
#include <vector>

#include "backends/gl/egl_library.h"

namespace sdfreel {

struct EglDevice {
  int index = 0;  // position in eglQueryDevicesEXT's list
  EGLDeviceEXT handle = nullptr;
  std::string name;         // EGL_RENDERER_EXT where offered, else the DRM node or "software"
  std::string vendor;       // EGL_VENDOR of the device where offered
  bool software = false;    // EGL_MESA_device_software
  std::string drm_node;     // EGL_DRM_DEVICE_FILE_EXT, e.g. /dev/dri/card0
  std::string render_node;  // EGL_DRM_RENDER_NODE_FILE_EXT, e.g. /dev/dri/renderD128
  int cuda_index = -1;      // EGL_CUDA_DEVICE_NV (NVIDIA), -1 when not offered
  std::string extensions;   // the device's extension string
};

// Every device, in EGL's order; empty where the library cannot enumerate devices.
std::vector<EglDevice> egl_devices(const EglLibrary& egl);

// The device that `choice` names ("software", "gpu" or an index). Throws GlPlatformError naming
// the devices there are when none matches.
EglDevice choose_egl_device(const std::vector<EglDevice>& devices, const std::string& choice);

// "0 software (llvmpipe), 1 NVIDIA ... (/dev/dri/renderD128)": for error messages.
std::string describe_devices(const std::vector<EglDevice>& devices);

}  // namespace sdfreel
