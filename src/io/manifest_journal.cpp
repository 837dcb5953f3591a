#include "io/manifest_journal.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/bounded_read.h"
#include "timeline/sha256.h"

namespace sdfreel {

using nlohmann::json;

std::string render_key(const ManifestHeader& h) {
  json identity = {h.timeline_parsed_sha256,
                   h.scene,
                   h.backend,
                   h.versions,
                   h.width,
                   h.height,
                   h.fps_num,
                   h.fps_den,
                   h.frame_count,
                   h.samples,
                   h.quality,
                   h.color_config,
                   h.display,
                   h.view};
  if (!h.adaptive.empty()) identity.push_back(h.adaptive);  // older keys stay as they were
  return sha256_hex(identity.dump()).substr(0, 32);
}

void append_journal(const std::string& dir, const std::string& key, const ManifestFrame& frame) {
  const std::string path = dir + "/manifest.journal";
  const std::string line =
      json{{"render", key}, {"frame", manifest_frame_json(frame)}}.dump() + "\n";
  const int fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  // A line torn by a kill or a full disk has no newline: end it, so this line stays readable.
  struct stat st {};
  char last = '\n';
  int err = ::fstat(fd, &st) != 0 ? errno : 0;
  if (err == 0 && st.st_size > 0 && ::pread(fd, &last, 1, st.st_size - 1) != 1) err = errno;
  if (err == 0 && last != '\n') err = write_fully(fd, "\n", 1);
  if (err == 0) err = write_fully(fd, line.data(), line.size());
  if (err != 0) {
    ::close(fd);
  } else {
    err = sync_and_close(fd);
  }
  if (err != 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(err));
}

void merge_journal(const std::string& dir, const std::string& key, Manifest& m) {
  const std::optional<std::string> text =
      read_regular_file(dir + "/manifest.journal", kMaxManifestBytes);
  if (text) merge_journal_text(*text, key, m);
}

void merge_journal_text(const std::string& text, const std::string& key, Manifest& m) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // no final newline: torn by a kill, never trusted
    try {
      const json j = json::parse(line);
      if (j.at("render") != key) continue;
      const ManifestFrame f = manifest_frame_from_json(j.at("frame"), m.header.frame_count);
      m.frames[f.index] = f;
    } catch (const std::exception&) {
      // damaged line: its frame is rendered again
    }
  }
}

void clear_journal(const std::string& dir) {
  const std::string path = dir + "/manifest.journal";
  if (::truncate(path.c_str(), 0) != 0 && errno != ENOENT)
    throw std::runtime_error("cannot empty " + path + ": " + std::strerror(errno));
}

}  // namespace sdfreel
