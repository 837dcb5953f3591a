#include "cli/folder_check.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "io/frame_files.h"
#include "io/hashing.h"
#include "io/manifest.h"

namespace sdfreel::test {

namespace fs = std::filesystem;

std::string FolderReport::describe() const {
  std::string out;
  for (const std::string& p : problems) out += "  " + p + "\n";
  return out;
}

std::vector<std::string> temporaries_in(const std::string& dir) {
  std::vector<std::string> found;
  for (const std::string sub : {"", "/frames"}) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir + sub, ec)) {
      const std::string name = e.path().filename().string();
      if (name.find("tmp") != std::string::npos)
        found.push_back((sub.empty() ? "" : "frames/") + name);
    }
  }
  return found;
}

namespace {

// Display MD5 of every frame of a video, decoded by stock ffmpeg (rgb48le, as framemd5 hashes).
std::vector<std::string> video_md5s(const std::string& path, std::string* error) {
  const RunResult r =
      run("ffmpeg -v error -i '" + path + "' -pix_fmt rgb48le -fflags +bitexact -f framemd5 -");
  if (r.status != 0 || !r.err.empty()) *error = "ffmpeg: " + r.err;
  std::vector<std::string> md5s;
  for (const std::string& line : framemd5_data_lines(r.out))
    md5s.push_back(line.substr(line.rfind(' ') + 1));
  return md5s;
}

}  // namespace

FolderReport check_output_folder(const std::string& dir, const std::string& video,
                                 bool allow_temporaries) {
  FolderReport rep;
  auto problem = [&](const std::string& p) { rep.problems.push_back(p); };
  std::optional<Manifest> m;
  try {
    m = read_manifest(dir + "/manifest.json");
  } catch (const std::exception& e) {
    problem(std::string("manifest unreadable: ") + e.what());
  }
  // Listed frames: complete and matching their hashes.
  std::map<int, std::string> listed_md5;
  if (m) {
    rep.listed = int(m->frames.size());
    for (const auto& [i, f] : m->frames) {
      char name[32];
      std::snprintf(name, sizeof name, "/frames/%05d.", i);
      listed_md5[i] = f.display_md5;
      try {
        if (md5_rgb48le(read_png16(dir + name + "png")) != f.display_md5)
          problem(std::string("listed frame ") + name + "png differs from its hash");
        if (linear_half_hash(read_exr(dir + name + "exr")) != f.linear_hash)
          problem(std::string("listed frame ") + name + "exr differs from its hash");
      } catch (const std::exception& e) {
        problem(std::string("listed frame ") + std::to_string(i) + ": " + e.what());
      }
    }
  }
  // Nothing torn under a final name, listed or not.
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir + "/frames", ec)) {
    const std::string path = e.path().string(), ext = e.path().extension().string();
    try {
      if (ext == ".png") read_png16(path);
      if (ext == ".exr") read_exr(path);
    } catch (const std::exception& err) {
      problem("torn frame published: " + path + ": " + err.what());
    }
  }
  if (!allow_temporaries)
    for (const std::string& t : temporaries_in(dir)) problem("temporary left: " + t);
  // A published video holds exactly the timeline's frames, all of them listed.
  if (!video.empty() && fs::exists(dir + "/" + video)) {
    rep.has_video = true;
    if (have_tool("ffmpeg")) {
      std::string error;
      const std::vector<std::string> md5s = video_md5s(dir + "/" + video, &error);
      if (!error.empty()) problem("video does not decode: " + error);
      if (!m || md5s.size() != size_t(m->header.frame_count))
        problem("video has " + std::to_string(md5s.size()) + " frames");
      for (size_t i = 0; i < md5s.size(); ++i)
        if (!listed_md5.count(int(i)) || listed_md5[int(i)] != md5s[i])
          problem("video frame " + std::to_string(i) + " is not the listed frame");
    }
  }
  return rep;
}

}  // namespace sdfreel::test
