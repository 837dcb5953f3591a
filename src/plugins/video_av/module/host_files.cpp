// io/atomic_file.h's functions in the module: sdfreel's own, passed in by attach()
// (io/video_module.h), so the video's file operations are counted with the process's others.
#include "io/atomic_file.h"
#include "plugins/video_av/module/host.h"

namespace sdfreel {

namespace {
VideoHost host_functions;
}  // namespace

void attach_host(const VideoHost& host) {
  host_functions = host;
}

std::string temp_path_for(const std::string& path) {
  return host_functions.temp_path_for(path);
}

int write_fully(int fd, const void* data, size_t size) {
  return host_functions.write_fully(fd, data, size);
}

int sync_and_close(int fd) {
  return host_functions.sync_and_close(fd);
}

void commit_temp_file(const std::string& temp, const std::string& path) {
  host_functions.commit_temp_file(temp, path);
}

void discard_temp_file(const std::string& temp) noexcept {
  host_functions.discard_temp_file(temp);
}

}  // namespace sdfreel
