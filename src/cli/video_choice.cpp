#include "cli/video_choice.h"

#include "pipeline/errors.h"
#include "timeline/rules.h"

namespace sdfreel {

std::string codec_of_output(const std::string& name, const std::string& render_codec,
                            const std::string& option) {
  const std::string usual = usual_codec(name);
  if (usual.empty() || usual == render_codec || !container_holds(name, render_codec))
    return usual.empty() ? render_codec : usual;
  // Refused rather than writing a codec the user may not expect over a file of the other.
  const std::string choose = option == "-o"
                                 ? "say which with --codec " + usual + " or --codec " + render_codec
                                 : "set [output] codec to the one you want";
  throw UsageError(option + " " + name + ": this container holds " + usual +
                   " or the render's codec " + render_codec + "; " + choose);
}

}  // namespace sdfreel
