#include "id_images.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "agreement.h"
#include "io/png_file.h"

namespace sdfreel::mesh_bench {
namespace {

using Rgb = std::vector<unsigned char>;

void put(Rgb& px, size_t i, unsigned char r, unsigned char g, unsigned char b) {
  px[i * 3] = r, px[i * 3 + 1] = g, px[i * 3 + 2] = b;
}

// A colour per id (an integer hash), black for nothing drawn.
void id_colour(Rgb& px, size_t i, uint32_t id, int dim) {
  if (id == 0) return put(px, i, 0, 0, 0);
  uint32_t h = id * 0x9E3779B1u;
  h ^= h >> 15, h *= 0x85EBCA77u, h ^= h >> 13;
  put(px, i, (64 + (h & 191)) / dim, (64 + ((h >> 8) & 191)) / dim, (64 + ((h >> 16) & 191)) / dim);
}

void write(const std::string& path, const SampleHits& s, const Rgb& px) {
  const std::vector<unsigned char> png = encode_png(s.width, s.height, 3, 8, px.data());
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

Rgb ids_of_first_sample(const SampleHits& s, int dim) {
  Rgb px(size_t(s.width) * s.height * 3);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      id_colour(px, size_t(y) * s.width + x, s.id[s.index(0, x, y)], dim);
  return px;
}

}  // namespace

void write_id_images(const std::string& dir, const std::string& name, const SampleHits& raster,
                     const SampleHits& embree, const CameraModel& camera) {
  write(dir + "/" + name + "_raster.png", raster, ids_of_first_sample(raster, 1));
  write(dir + "/" + name + "_embree.png", embree, ids_of_first_sample(embree, 1));
  Rgb diff = ids_of_first_sample(raster, 3);
  for (int s = 0; s < raster.samples; ++s)
    for (int y = 0; y < raster.height; ++y)
      for (int x = 0; x < raster.width; ++x) {
        const size_t i = raster.index(s, x, y), p = size_t(y) * raster.width + x;
        const uint32_t a = raster.id[i], b = embree.id[i];
        if (a == b) continue;
        if ((a == 0) != (b == 0)) {
          put(diff, p, 0, 255, 0);
          continue;
        }
        const double da = view_depth(camera, raster.depth[i]);
        const double db = view_depth(camera, embree.depth[i]);
        const bool tie = std::abs(da - db) <= TIE_RELATIVE_DEPTH * std::max(da, db);
        if (tie)
          put(diff, p, 255, 255, 0);
        else
          put(diff, p, 255, 0, 0);
      }
  write(dir + "/" + name + "_diff.png", raster, diff);
}

}  // namespace sdfreel::mesh_bench
