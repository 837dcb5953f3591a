#include "cli/verify_tolerance.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/output_folder.h"
#include "io/display_compare.h"
#include "io/frame_files.h"

namespace sdfreel {

int verify_within_tolerance(FramePipeline& pipe, const std::vector<int>& frames,
                            const std::string& golden_dir, const std::string& out_dir) {
  int checked = 0, failed = 0;
  double worst_psnr = INFINITY;
  for (int i : frames) {
    const std::string golden = frame_path(golden_dir, i, "png");
    if (!std::filesystem::exists(golden)) continue;
    const ImageRGB16 want = read_png16(golden);
    const RenderedFrame f = pipe.render(i);
    if (want.width != f.display.width || want.height != f.display.height) {
      std::fprintf(stderr, "sdfreel: verify failed: %s is %dx%d, the frame %dx%d\n", golden.c_str(),
                   want.width, want.height, f.display.width, f.display.height);
      return 1;
    }
    const ToleranceVerdict v = filament_rule(want, f.display);
    ++checked;
    worst_psnr = std::min(worst_psnr, v.psnr_db);
    std::string note;
    if (!v.pass) {
      ++failed;
      std::filesystem::create_directories(out_dir);
      char name[64];
      std::snprintf(name, sizeof name, "/verify-%05d-", i);
      write_png16_atomic(out_dir + name + "rendered.png", f.display);
      write_png16_atomic(out_dir + name + "diff.png", difference_image(want, f.display, 16.0));
      note = "; wrote " + out_dir + name + "diff.png";
    }
    std::fprintf(stderr,
                 "frame %05d %s: mean %.3f/255, %.3f%% over 5/255, max %.1f/255, PSNR %.2f dB%s\n",
                 i, v.pass ? "within tolerance" : "OUTSIDE tolerance", v.difference.mean,
                 100.0 * v.share_over_5, v.difference.max, v.psnr_db, note.c_str());
  }
  if (checked == 0) {
    std::fprintf(stderr,
                 "sdfreel: verify failed: no golden PNG frames for the selected frames "
                 "in %s/frames (render the reference with frames = [\"png\"])\n",
                 golden_dir.c_str());
    return 1;
  }
  if (failed > 0) {
    std::fprintf(stderr,
                 "sdfreel: verify failed: %d of %d frames outside Filament's tolerance (at most "
                 "0.1%% of pixels over 5/255, mean under 0.5/255)\n",
                 failed, checked);
    return 1;
  }
  std::fprintf(stderr, "verified %d frames within tolerance (lowest PSNR %.2f dB)\n", checked,
               worst_psnr);
  return 0;
}

}  // namespace sdfreel
