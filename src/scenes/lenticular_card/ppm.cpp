#include "scenes/lenticular_card/ppm.h"

#include <fstream>
#include <iterator>
#include <sstream>

namespace sdfreel::lenticular_card {

std::string encode_ppm(const Rgb8Image& img) {
  std::string out =
      "P6\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n255\n";
  out.append(reinterpret_cast<const char*>(img.rgb.data()), img.rgb.size());
  return out;
}

bool read_ppm(const std::string& path, Rgb8Image& img) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::string magic;
  int w = 0, h = 0, maxval = 0;
  f >> magic >> w >> h >> maxval;
  if (!f || magic != "P6" || maxval != 255 || w < 1 || h < 1 || w > 65536 || h > 65536)
    return false;
  f.get();  // the one whitespace byte before the pixels
  Rgb8Image read(w, h);
  f.read(reinterpret_cast<char*>(read.rgb.data()), std::streamsize(read.rgb.size()));
  if (f.gcount() != std::streamsize(read.rgb.size()) || f.peek() != EOF) return false;
  img = std::move(read);
  return true;
}

}  // namespace sdfreel::lenticular_card
