#include "io/build_id.h"

#include <elf.h>
#include <link.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstring>

namespace sdfreel {

namespace {

constexpr size_t align4(size_t n) {
  return (n + 3) & ~size_t(3);
}

// dl_iterate_phdr visits the main program first: read its NT_GNU_BUILD_ID note and stop.
int find_build_id(struct dl_phdr_info* info, size_t, void* out) {
  auto* id = static_cast<std::string*>(out);
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& ph = info->dlpi_phdr[i];
    if (ph.p_type != PT_NOTE) continue;
    const auto* p = reinterpret_cast<const unsigned char*>(info->dlpi_addr + ph.p_vaddr);
    const unsigned char* end = p + ph.p_memsz;
    while (p + sizeof(ElfW(Nhdr)) <= end) {
      ElfW(Nhdr) note;
      std::memcpy(&note, p, sizeof note);
      const unsigned char* name = p + sizeof note;
      const unsigned char* desc = name + align4(note.n_namesz);
      if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 &&
          std::memcmp(name, "GNU", 4) == 0 && desc + note.n_descsz <= end) {
        char hex[3];
        for (size_t k = 0; k < note.n_descsz; ++k) {
          std::snprintf(hex, sizeof hex, "%02x", desc[k]);
          *id += hex;
        }
        return 1;
      }
      p = desc + align4(note.n_descsz);
    }
  }
  return 1;  // only the main program counts
}

std::string executable_stamp() {
  struct stat st {};
  if (::stat("/proc/self/exe", &st) != 0) return {};
  return "size" + std::to_string(st.st_size) + "-mtime" + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

}  // namespace

const std::string& build_id() {
  static const std::string id = [] {
    std::string found;
    dl_iterate_phdr(find_build_id, &found);
    return found.empty() ? executable_stamp() : found;
  }();
  return id;
}

}  // namespace sdfreel
