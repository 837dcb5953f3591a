#include "backends/gl/egl_devices.h"

#include <cctype>

#include "backends/gl/gl_platform.h"

namespace sdfreel {

namespace {

std::string device_string(const EglLibrary& egl, EGLDeviceEXT d, EGLint what) {
  const char* s = egl.QueryDeviceStringEXT(d, what);
  return s ? s : "";
}

bool is_index(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

}  // namespace

std::vector<EglDevice> egl_devices(const EglLibrary& egl) {
  std::vector<EglDevice> out;
  const char* client = egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!egl.has_devices() || !EglLibrary::has_extension(client, "EGL_EXT_device_enumeration"))
    return out;
  EGLint count = 0;
  if (!egl.QueryDevicesEXT(0, nullptr, &count) || count <= 0) return out;
  std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count));
  if (!egl.QueryDevicesEXT(count, handles.data(), &count)) return out;
  handles.resize(static_cast<size_t>(count));
  for (size_t i = 0; i < handles.size(); ++i) {
    EglDevice d;
    d.index = int(i);
    d.handle = handles[i];
    d.extensions = device_string(egl, d.handle, EGL_EXTENSIONS);
    const char* ext = d.extensions.c_str();
    d.software = EglLibrary::has_extension(ext, "EGL_MESA_device_software");
    if (EglLibrary::has_extension(ext, "EGL_EXT_device_drm"))
      d.drm_node = device_string(egl, d.handle, EGL_DRM_DEVICE_FILE_EXT);
    if (EglLibrary::has_extension(ext, "EGL_EXT_device_drm_render_node"))
      d.render_node = device_string(egl, d.handle, EGL_DRM_RENDER_NODE_FILE_EXT);
    if (EglLibrary::has_extension(ext, "EGL_EXT_device_query_name")) {
      d.name = device_string(egl, d.handle, EGL_RENDERER_EXT);
      d.vendor = device_string(egl, d.handle, EGL_VENDOR);
    }
    EGLAttrib cuda = -1;
    if (EglLibrary::has_extension(ext, "EGL_NV_device_cuda") && egl.QueryDeviceAttribEXT &&
        egl.QueryDeviceAttribEXT(d.handle, EGL_CUDA_DEVICE_NV, &cuda))
      d.cuda_index = int(cuda);
    if (d.name.empty())
      d.name = d.software ? "software" : !d.render_node.empty() ? d.render_node : d.drm_node;
    if (d.name.empty()) d.name = "device " + std::to_string(i);
    out.push_back(d);
  }
  return out;
}

std::string describe_devices(const std::vector<EglDevice>& devices) {
  if (devices.empty()) return "EGL lists no devices";
  std::string s;
  for (const EglDevice& d : devices) {
    if (!s.empty()) s += ", ";
    s += std::to_string(d.index) + " " + (d.software ? "software" : "gpu") + " (" + d.name;
    if (!d.render_node.empty()) s += ", " + d.render_node;
    s += ")";
  }
  return s;
}

EglDevice choose_egl_device(const std::vector<EglDevice>& devices, const std::string& choice) {
  for (const EglDevice& d : devices) {
    if (choice == "software" && d.software) return d;
    if (choice == "gpu" && !d.software) return d;
    if (is_index(choice) && std::to_string(d.index) == choice) return d;
  }
  if (choice != "software" && choice != "gpu" && !is_index(choice))
    throw GlPlatformError("unknown GL device '" + choice +
                          "': use software, gpu or an index from `sdfreel devices`");
  throw GlPlatformError("no EGL device '" + choice + "' on this machine; there are: " +
                        describe_devices(devices) + " (see `sdfreel devices`)");
}

}  // namespace sdfreel
