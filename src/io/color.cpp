// Display transform: scene-linear Rec.709 -> display, quantised to 16 bits; the shipped views in
// sdfreel's own math, every other through OpenColorIO.
#include "io/color.h"

#include <OpenColorIO/OpenColorIO.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "io/distinct_pixels.h"
#include "io/quantise16.h"
#include "io/shipped_views.h"
#include "render/data_files.h"

namespace OCIO = OCIO_NAMESPACE;
namespace fs = std::filesystem;

namespace sdfreel {
namespace {

const char* kConfigRelative = "ocio/config.ocio";

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + ("\"" + s + "\"");
  return out.empty() ? "(none)" : out;
}

// "builtin" -> the shipped file; "env" or "$OCIO" -> the OCIO environment variable; else a path.
std::string resolve_config_path(const std::string& config) {
  if (config == "builtin") return builtin_ocio_config_path();
  if (config == "env" || config == "$OCIO") {
    const char* env = std::getenv("OCIO");
    if (!env || !*env)
      throw std::runtime_error("OCIO config \"" + config +
                               "\" asks for the OCIO environment variable, which is not set");
    return env;
  }
  return config;
}

OCIO::ConstConfigRcPtr load_config(const std::string& config) {
  const std::string path = resolve_config_path(config);
  if (!is_file(path))
    throw std::runtime_error("OCIO config \"" + config + "\": file not found: " + path);
  try {
    OCIO::ConstConfigRcPtr cfg = OCIO::Config::CreateFromFile(path.c_str());
    cfg->validate();
    return cfg;
  } catch (const OCIO::Exception& e) {
    throw std::runtime_error("OCIO config \"" + path + "\" is invalid: " + e.what());
  }
}

std::vector<std::string> displays_of(const OCIO::ConstConfigRcPtr& cfg) {
  std::vector<std::string> out;
  for (int i = 0; i < cfg->getNumDisplays(); ++i) out.push_back(cfg->getDisplay(i));
  return out;
}

std::vector<std::string> views_of(const OCIO::ConstConfigRcPtr& cfg, const std::string& display) {
  std::vector<std::string> out;
  for (int i = 0; i < cfg->getNumViews(display.c_str()); ++i)
    out.push_back(cfg->getView(display.c_str(), i));
  return out;
}

bool contains(const std::vector<std::string>& items, const std::string& s) {
  return std::find(items.begin(), items.end(), s) != items.end();
}

// Rows converted per OCIO call: bounds the scratch buffer without per-pixel call overhead.
constexpr int kRowsPerChunk = 16;

}  // namespace

std::string builtin_ocio_config_path() {
  if (const char* env = std::getenv("SDFREEL_OCIO_CONFIG"); env && *env) return env;

  const std::vector<fs::path> candidates = data_file_candidates(kConfigRelative);
  std::error_code ec;
  for (const auto& c : candidates)
    if (is_file(c)) return fs::weakly_canonical(c, ec).string();

  std::string tried;
  for (const auto& c : candidates) tried += "\n  " + c.string();
  throw std::runtime_error(
      "cannot find the shipped OCIO config (set SDFREEL_OCIO_CONFIG to its path); tried:" + tried);
}

struct DisplayTransform::Impl {
  std::string description;
  // The shipped config's views are sdfreel's own math (io/shipped_views.h); every other view is
  // OpenColorIO's CPU processor.
  ShippedViewPixels shipped = nullptr;
  OCIO::ConstCPUProcessorRcPtr cpu;

  void convert(float* rgba, int width, int rows) const {
    if (!shipped) {
      OCIO::PackedImageDesc desc(rgba, width, rows, 4);
      cpu->apply(desc);
      return;
    }
    convert_distinct(rgba, size_t(width) * rows, shipped);
  }
};

DisplayTransform::DisplayTransform(const std::string& config, const std::string& display,
                                   const std::string& view)
    : impl_(std::make_unique<Impl>()) {
  impl_->description = config + " / " + display + " / " + view;
  // The shipped config's own views are sdfreel's math: no need to parse the config (1-2 ms, twice
  // a render) when the names are the shipped ones; any other name is checked by OCIO below.
  if (config == "builtin") {
    builtin_ocio_config_path();  // the shipped file is still required (an install missing it fails)
    impl_->shipped = shipped_view_pixels(display, view);
    if (impl_->shipped) return;
  }
  OCIO::ConstConfigRcPtr cfg = load_config(config);
  const auto displays = displays_of(cfg);
  if (!contains(displays, display))
    throw std::runtime_error("OCIO config \"" + config + "\" has no display \"" + display +
                             "\"; displays: " + join(displays));
  const auto views = views_of(cfg, display);
  if (!contains(views, view))
    throw std::runtime_error("OCIO display \"" + display + "\" has no view \"" + view +
                             "\"; views: " + join(views));
  if (!cfg->hasRole(OCIO::ROLE_SCENE_LINEAR))
    throw std::runtime_error("OCIO config \"" + config + "\" defines no scene_linear role");

  try {
    OCIO::DisplayViewTransformRcPtr dvt = OCIO::DisplayViewTransform::Create();
    dvt->setSrc(OCIO::ROLE_SCENE_LINEAR);
    dvt->setDisplay(display.c_str());
    dvt->setView(view.c_str());
    OCIO::ConstProcessorRcPtr proc = cfg->getProcessor(dvt);
    impl_->cpu = proc->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                                OCIO::OPTIMIZATION_DEFAULT);
  } catch (const OCIO::Exception& e) {
    throw std::runtime_error("OCIO cannot build display \"" + display + "\" / view \"" + view +
                             "\": " + e.what());
  }

  // This variable makes OCIO override the optimisation chosen above, which can change pixels:
  // record it so that a hash mismatch explains itself.
  if (const char* flags = std::getenv("OCIO_OPTIMIZATION_FLAGS"); flags && *flags)
    impl_->description += std::string(" (OCIO_OPTIMIZATION_FLAGS=") + flags + ")";
}

DisplayTransform::~DisplayTransform() = default;

ImageRGB16 DisplayTransform::apply(const ImageRGBA& linear) const {
  ImageRGB16 out(linear.width, linear.height);
  const size_t row_floats = size_t(linear.width) * 4;
  const int chunks = (linear.height + kRowsPerChunk - 1) / kRowsPerChunk;
  // The ACES output transform costs close to a microsecond a pixel in OCIO, so chunks of rows run
  // in parallel. Each pixel is converted on its own, so the result does not depend on the split;
  // the OCIO CPU processor is thread-safe and the scratch buffers are per task.
  tbb::parallel_for(tbb::blocked_range<int>(0, chunks), [&](const tbb::blocked_range<int>& r) {
    std::vector<float> scratch;
    for (int chunk = r.begin(); chunk != r.end(); ++chunk) {
      const int y0 = chunk * kRowsPerChunk;
      const int rows = std::min(kRowsPerChunk, linear.height - y0);
      const float* src = linear.pixels.data() + size_t(y0) * row_floats;
      scratch.assign(src, src + size_t(rows) * row_floats);
      impl_->convert(scratch.data(), linear.width, rows);
      uint16_t* dst = out.pixels.data() + size_t(y0) * linear.width * 3;
      const size_t n = size_t(rows) * linear.width;
      for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) dst[i * 3 + c] = quantise16(scratch[i * 4 + c]);
    }
  });
  return out;
}

std::string DisplayTransform::description() const {
  return impl_->description;
}

std::vector<std::string> ocio_displays(const std::string& config) {
  return displays_of(load_config(config));
}

std::vector<std::string> ocio_views(const std::string& config, const std::string& display) {
  return views_of(load_config(config), display);
}

}  // namespace sdfreel
