#pragma once
// The one check every fault-injection test ends with: every frame the manifest lists is complete
// and matches its hash, nothing torn is published under a final name, no temporary is left by a
// finished writer, and a published video decodes to exactly the listed frames.
#include <string>
#include <vector>

#include "cli/harness.h"

namespace sdfreel::test {

struct FolderReport {
  std::vector<std::string> problems;  // empty: consistent
  int listed = 0;                     // frames the manifest (with its journal) lists
  bool has_video = false;
  std::string describe() const;
};

// Checks DIR (a render's output folder). `video` is the video's file name ("" for none). With
// `allow_temporaries`, hidden temporaries of killed writers are not problems (render's start-up
// removes them).
FolderReport check_output_folder(const std::string& dir, const std::string& video,
                                 bool allow_temporaries = false);

// "frames/00003.png"-style names of the files in DIR/frames and DIR whose name contains "tmp".
std::vector<std::string> temporaries_in(const std::string& dir);

}  // namespace sdfreel::test
