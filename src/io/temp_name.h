#pragma once
// Names of temporary files (".NAME.tmp-HOST-PID-N"): which host and process is writing them, so
// that start-up cleanup on shared storage removes only this host's temporaries of dead processes.
#include <string>

namespace sdfreel {

// This machine's host name, with characters unfit for a file name replaced by '_'.
const std::string& temp_host_name();

struct TempName {
  bool valid = false;  // false for any other file name
  std::string host;
  long pid = 0;
};

// Reads the host and PID from a file name made by temp_path_for.
TempName parse_temp_name(const std::string& file_name);

}  // namespace sdfreel
