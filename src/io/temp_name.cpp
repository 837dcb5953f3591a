#include "io/temp_name.h"

#include <unistd.h>

#include <charconv>

namespace sdfreel {
namespace {

std::string read_host_name() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "unknown-host";
  std::string host(buf);
  for (char& c : host) {
    const bool fits = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '.';
    if (!fits) c = '_';
  }
  return host;
}

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

}  // namespace

const std::string& temp_host_name() {
  static const std::string host = read_host_name();
  return host;
}

TempName parse_temp_name(const std::string& file_name) {
  TempName t;
  const size_t at = file_name.rfind(".tmp-");
  if (file_name.empty() || file_name[0] != '.' || at == std::string::npos) return t;
  // HOST-PID-N, read from the right: a host name may itself contain '-'.
  const std::string rest = file_name.substr(at + 5);
  const size_t n_dash = rest.rfind('-');
  if (n_dash == std::string::npos || n_dash == 0) return t;
  const size_t pid_dash = rest.rfind('-', n_dash - 1);
  if (pid_dash == std::string::npos || pid_dash == 0) return t;
  const std::string pid = rest.substr(pid_dash + 1, n_dash - pid_dash - 1);
  if (!all_digits(pid) || !all_digits(rest.substr(n_dash + 1))) return t;
  const auto r = std::from_chars(pid.data(), pid.data() + pid.size(), t.pid);
  if (r.ec != std::errc() || t.pid <= 0) return t;
  t.host = rest.substr(0, pid_dash);
  t.valid = true;
  return t;
}

}  // namespace sdfreel
