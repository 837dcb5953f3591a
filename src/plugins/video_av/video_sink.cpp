#include "plugins/video_av/video_sink.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "io/atomic_file.h"

namespace sdfreel {
namespace {

constexpr int kBufferBytes = 1 << 16;

}  // namespace

VideoFileSink::VideoFileSink(const std::string& final_path)
    : final_(final_path), temp_(temp_path_for(final_path)) {
  fd_ = ::open(temp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error("video: cannot create " + temp_ + ": " + std::strerror(errno));
  auto* buffer = static_cast<unsigned char*>(av_malloc(kBufferBytes));
  if (buffer)
    avio_ = avio_alloc_context(buffer, kBufferBytes, /*write_flag=*/1, this, nullptr,
                               &VideoFileSink::write_packet, &VideoFileSink::seek);
  if (!avio_) {
    av_free(buffer);
    ::close(fd_);
    discard_temp_file(temp_);
    throw std::runtime_error("video: out of memory");
  }
}

VideoFileSink::~VideoFileSink() {
  if (avio_) {
    av_freep(&avio_->buffer);
    avio_context_free(&avio_);
  }
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) discard_temp_file(temp_);
}

int VideoFileSink::write_packet(void* opaque, PacketBytes buf, int size) {
  auto* self = static_cast<VideoFileSink*>(opaque);
  if (self->error_ == 0 && ::lseek(self->fd_, self->position_, SEEK_SET) < 0) self->error_ = errno;
  if (self->error_ == 0) self->error_ = write_fully(self->fd_, buf, size_t(size));
  if (self->error_ != 0) return AVERROR(self->error_);
  self->position_ += size;
  self->end_ = std::max(self->end_, self->position_);
  return size;
}

int64_t VideoFileSink::seek(void* opaque, int64_t offset, int whence) {
  auto* self = static_cast<VideoFileSink*>(opaque);
  switch (whence & ~AVSEEK_FORCE) {
    case AVSEEK_SIZE:
      return self->end_;
    case SEEK_SET:
      break;
    case SEEK_CUR:
      offset += self->position_;
      break;
    case SEEK_END:
      offset += self->end_;
      break;
    default:
      return AVERROR(EINVAL);
  }
  if (offset < 0) return AVERROR(EINVAL);
  self->position_ = offset;
  return offset;
}

void VideoFileSink::commit() {
  avio_flush(avio_);
  int err = error_ ? error_ : avio_->error < 0 ? EIO : 0;
  struct stat st {};
  if (err == 0 && ::fstat(fd_, &st) != 0) err = errno;
  if (err == 0 && st.st_size != end_) err = ENOSPC;  // a short file is never published
  if (err == 0) {
    err = sync_and_close(fd_);
    fd_ = -1;
  }
  if (err != 0)
    throw std::runtime_error("video: cannot write " + final_ + ": " + std::strerror(err));
  commit_temp_file(temp_, final_);
  committed_ = true;
}

}  // namespace sdfreel
