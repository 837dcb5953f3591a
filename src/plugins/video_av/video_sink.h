#pragma once
// Where the muxer's bytes go: a temporary file unique to this writer (".NAME.tmp-HOST-PID-N"
// beside the video), written through a custom AVIOContext so that every write is checked (a full
// disk fails the encode) and published by rename only when complete. Two writers of one video never
// share a temporary file, and the last complete one wins the rename.
#include <string>

#include "plugins/video_av/video_av.h"

namespace sdfreel {

class VideoFileSink {
 public:
  explicit VideoFileSink(const std::string& final_path);  // throws std::runtime_error
  ~VideoFileSink();  // without commit(): removes the temporary file
  VideoFileSink(const VideoFileSink&) = delete;
  VideoFileSink& operator=(const VideoFileSink&) = delete;

  AVIOContext* avio() { return avio_; }
  const std::string& temp_path() const { return temp_; }
  // Flushes, checks that every byte reached the file, fsyncs, closes and renames into place.
  void commit();

 private:
  // FFmpeg 7 (libavformat 61, Debian 13) made the buffer const; FFmpeg 5 (Debian 12) has it not.
#if LIBAVFORMAT_VERSION_MAJOR >= 61
  using PacketBytes = const uint8_t*;
#else
  using PacketBytes = uint8_t*;
#endif
  static int write_packet(void* opaque, PacketBytes buf, int size);
  static int64_t seek(void* opaque, int64_t offset, int whence);

  std::string final_, temp_;
  int fd_ = -1;
  int error_ = 0;         // first errno of a failed write
  int64_t position_ = 0;  // where the next write goes
  int64_t end_ = 0;       // bytes in the file (largest offset written)
  AVIOContext* avio_ = nullptr;
  bool committed_ = false;
};

}  // namespace sdfreel
